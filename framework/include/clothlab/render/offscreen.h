/// @file offscreen.h
/// @brief An offscreen OpenGL context in memory through OSMesa (no display, no window).
///
/// Only programs linked with libOSMesa (clothlab-render and the render tests) contain this code.
#pragma once
#include <vector>

#include "clothlab/render/image.h"

namespace clothlab {

/// A compatibility-profile OSMesa context rendering into an RGBA buffer with a 24-bit depth buffer.
class OffscreenContext {
public:
    /// Creates the context and makes it current.
    /// @param width, height  buffer size in pixels
    /// @throws std::runtime_error when OSMesa cannot create a context
    OffscreenContext(int width, int height);
    ~OffscreenContext();
    OffscreenContext(const OffscreenContext&) = delete;
    OffscreenContext& operator=(const OffscreenContext&) = delete;

    /// Width of the buffer in pixels.
    int width() const { return width_; }
    /// Height of the buffer in pixels.
    int height() const { return height_; }
    /// Makes this context current again (after another one was used).
    void makeCurrent();
    /// Waits for rendering to finish and returns the buffer, top row first.
    Image read();

private:
    void* ctx_ = nullptr;                 ///< the OSMesaContext
    int width_ = 0, height_ = 0;          ///< size
    std::vector<unsigned char> buffer_;   ///< the colour buffer OSMesa renders into (bottom row first)
};

}  // namespace clothlab
