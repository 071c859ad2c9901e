// An OSMesa context rendering into memory (linked only into clothlab-render and the render tests).
#include "clothlab/render/offscreen.h"

#include <GL/osmesa.h>

#include <algorithm>
#include <stdexcept>

#include "clothlab/render/renderer.h"

namespace clothlab {

OffscreenContext::OffscreenContext(int width, int height) : width_(width), height_(height) {
    // A compatibility-profile context (no profile attribute): the fixed-function pipeline and
    // ImGui's OpenGL2 backend both need it.
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,
                           OSMESA_ACCUM_BITS, 0, 0};
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!ctx) throw std::runtime_error("OSMesa: cannot create an offscreen OpenGL context");
    ctx_ = ctx;
    buffer_.resize(4 * static_cast<size_t>(width) * height);
    if (!OSMesaMakeCurrent(ctx, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
        OSMesaDestroyContext(ctx);
        ctx_ = nullptr;
        throw std::runtime_error("OSMesa: cannot make the context current");
    }
}

OffscreenContext::~OffscreenContext() {
    if (ctx_) OSMesaDestroyContext(static_cast<OSMesaContext>(ctx_));
}

void OffscreenContext::makeCurrent() {
    OSMesaMakeCurrent(static_cast<OSMesaContext>(ctx_), buffer_.data(), GL_UNSIGNED_BYTE, width_, height_);
}

Image OffscreenContext::read() {
    glFinish();
    return readPixels(width_, height_);
}

}  // namespace clothlab
