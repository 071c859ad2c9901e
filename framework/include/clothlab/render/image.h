/// @file image.h
/// @brief An RGBA image in memory, PNG files (stb_image_write / stb_image) and comparison.
#pragma once
#include <string>
#include <vector>

namespace clothlab {

/// 8-bit RGBA pixels, row-major, top row first.
struct Image {
    int width = 0;                     ///< pixels per row
    int height = 0;                    ///< rows
    std::vector<unsigned char> rgba;   ///< 4 * width * height bytes

    /// Pointer to pixel (x, y): 4 bytes R, G, B, A.
    /// @param x  column (0 = left), @param y  row (0 = top)
    const unsigned char* at(int x, int y) const { return &rgba[4 * (static_cast<size_t>(y) * width + x)]; }
};

/// Writes an image as PNG.
/// @param path   output file
/// @param image  the pixels
/// @throws InputError naming the file when it cannot be written
void writePng(const std::string& path, const Image& image);

/// Reads a PNG (or any format stb_image knows) as RGBA.
/// @param path  input file
/// @throws InputError naming the file when it cannot be read
Image readPng(const std::string& path);

/// How much two images of the same size differ.
struct ImageDiff {
    double mean = 0.0;         ///< mean absolute difference per channel (R, G, B), in [0, 255]
    double bad_fraction = 0.0; ///< fraction of pixels whose largest channel difference exceeds the threshold
};

/// Compares RGB of two images of equal size.
/// @param a, b       the images
/// @param threshold  per-channel difference (0..255) above which a pixel counts as different
/// @throws std::invalid_argument if the sizes differ
ImageDiff compareImages(const Image& a, const Image& b, int threshold);

}  // namespace clothlab
