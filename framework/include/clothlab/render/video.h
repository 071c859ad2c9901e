/// @file video.h
/// @brief Video export: frames piped to ffmpeg (H.264 MP4) when ffmpeg is installed.
#pragma once
#include <cstdio>
#include <string>

#include "clothlab/render/image.h"

namespace clothlab {

/// True when an `ffmpeg` program is on the PATH.
bool ffmpegAvailable();

/// Writes frames of equal size to a video file through an ffmpeg process.
class VideoWriter {
public:
    /// Starts ffmpeg writing `path` at `fps` frames per second.
    /// @param path           output file, e.g. out/demo.mp4
    /// @param width, height  frame size in pixels
    /// @param fps            frames per second
    /// @throws InputError naming the file when ffmpeg is missing or cannot be started
    VideoWriter(const std::string& path, int width, int height, double fps);
    ~VideoWriter();
    VideoWriter(const VideoWriter&) = delete;
    VideoWriter& operator=(const VideoWriter&) = delete;
    /// Appends one frame (same size as given to the constructor).
    /// @param frame  the image
    void write(const Image& frame);
    /// Ends the stream and waits for ffmpeg; true when ffmpeg succeeded.
    bool close();

private:
    FILE* pipe_ = nullptr;  ///< ffmpeg's stdin
    std::string path_;      ///< output file
    int width_, height_;    ///< frame size
};

}  // namespace clothlab
