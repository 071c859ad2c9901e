// Video through an ffmpeg process reading raw RGBA frames on its stdin.
#include "clothlab/render/video.h"

#include <cstdlib>

#include "clothlab/core/input_error.h"

namespace clothlab {

bool ffmpegAvailable() { return std::system("command -v ffmpeg >/dev/null 2>&1") == 0; }

VideoWriter::VideoWriter(const std::string& path, int width, int height, double fps)
    : path_(path), width_(width), height_(height) {
    if (!ffmpegAvailable())
        throw InputError(path, "--video", "ffmpeg is not installed (apt-get install ffmpeg); the PNG frames are written anyway");
    const std::string cmd = "ffmpeg -loglevel error -y -f rawvideo -pix_fmt rgba -s " + std::to_string(width) + "x" +
                            std::to_string(height) + " -r " + std::to_string(fps) +
                            " -i - -c:v libx264 -pix_fmt yuv420p -crf 20 -movflags +faststart '" + path + "'";
    pipe_ = popen(cmd.c_str(), "w");
    if (!pipe_) throw InputError(path, "--video", "cannot start ffmpeg");
}

VideoWriter::~VideoWriter() { close(); }

void VideoWriter::write(const Image& frame) {
    if (pipe_ && frame.width == width_ && frame.height == height_)
        std::fwrite(frame.rgba.data(), 1, frame.rgba.size(), pipe_);
}

bool VideoWriter::close() {
    if (!pipe_) return true;
    const int rc = pclose(pipe_);
    pipe_ = nullptr;
    return rc == 0;
}

}  // namespace clothlab
