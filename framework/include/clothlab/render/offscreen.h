/// @file offscreen.h
/// @brief An offscreen OpenGL context in memory (no display, no window): OSMesa or EGL surfaceless.
///
/// One class, two implementations, and a program links exactly one of them (one process cannot use
/// libOSMesa and libGL/libOpenGL together, both define the gl* functions):
/// - `src/render/offscreen_osmesa.cpp`: an OSMesa context (libOSMesa) in `clothlab-render`;
/// - `src/render/offscreen_egl.cpp`: an EGL context without a window (libEGL + libOpenGL) on Mesa's
///   surfaceless platform, or else on the first EGL device, drawing into a framebuffer object, in
///   `clothlab-render-egl`.
/// Both give an OpenGL 3.3 core-profile context (what the renderer and its ImGui backend,
/// render/imgui_gl.h, are written for) with RGBA colour, 24-bit depth and 8-bit stencil; `./lab` picks the program (docs/render.md).
#pragma once
#include <memory>
#include <stdexcept>
#include <string>

#include "clothlab/render/image.h"

namespace clothlab {

/// No offscreen OpenGL context could be made (no library, no driver, no display); the message names
/// the backend and the failing call, e.g. "EGL: eglInitialize failed (EGL_NOT_INITIALIZED)".
class OffscreenError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// An OpenGL 3.3 core-profile context rendering into an RGBA buffer with a 24-bit depth buffer.
class OffscreenContext {
public:
    /// Creates the context and makes it current.
    /// @param width, height  buffer size in pixels
    /// @throws OffscreenError when the backend cannot create or bind a context
    OffscreenContext(int width, int height);
    /// Destroys the context and its buffers (EGL: the display stays initialised for other contexts).
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
    /// The backend and the GL renderer that draw, e.g. "OSMesa (llvmpipe)" or
    /// "EGL surfaceless (llvmpipe)": what `clothlab-render` prints as its "renderer:" line.
    const std::string& description() const { return description_; }

private:
    struct Impl;                   ///< the backend's handles (defined in its .cpp)
    std::unique_ptr<Impl> impl_;   ///< OSMesa context and buffer, or EGL display, context and framebuffer
    int width_ = 0, height_ = 0;   ///< size
    std::string description_;      ///< see description()
};

}  // namespace clothlab
