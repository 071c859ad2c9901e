// PNG in and out through stb (Debian libstb: the implementations live in libstb.so).
#include "clothlab/render/image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "clothlab/core/input_error.h"

namespace clothlab {

void writePng(const std::string& path, const Image& image) {
    if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(), 4 * image.width))
        throw InputError(path, "(file)", "cannot write the PNG");
}

Image readPng(const std::string& path) {
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 4);
    if (!data) throw InputError(path, "(file)", "cannot read the image");
    Image img;
    img.width = w;
    img.height = h;
    img.rgba.assign(data, data + 4 * static_cast<size_t>(w) * h);
    stbi_image_free(data);
    return img;
}

ImageDiff compareImages(const Image& a, const Image& b, int threshold) {
    if (a.width != b.width || a.height != b.height) throw std::invalid_argument("compareImages: sizes differ");
    ImageDiff d;
    long long sum = 0, bad = 0;
    const long long n = static_cast<long long>(a.width) * a.height;
    for (long long p = 0; p < n; ++p) {
        int worst = 0;
        for (int k = 0; k < 3; ++k) {
            const int diff = std::abs(int(a.rgba[4 * p + k]) - int(b.rgba[4 * p + k]));
            sum += diff;
            worst = std::max(worst, diff);
        }
        if (worst > threshold) ++bad;
    }
    d.mean = n ? double(sum) / (3.0 * n) : 0.0;
    d.bad_fraction = n ? double(bad) / n : 0.0;
    return d;
}

}  // namespace clothlab
