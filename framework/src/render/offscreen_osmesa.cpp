// The offscreen context through OSMesa, rendering into memory (linked only into clothlab-render and
// the render tests that use OSMesa; offscreen_egl.cpp is the other implementation of offscreen.h).
#include "clothlab/render/offscreen.h"

#include <GL/osmesa.h>

#include <vector>

#include "clothlab/render/renderer.h"

namespace clothlab {

struct OffscreenContext::Impl {
    OSMesaContext ctx = nullptr;
    std::vector<unsigned char> buffer;  // the colour buffer OSMesa renders into (bottom row first)
};

OffscreenContext::OffscreenContext(int width, int height) : impl_(std::make_unique<Impl>()), width_(width), height_(height) {
    // An OpenGL 3.3 core-profile context, what the renderer and its ImGui backend are written for.
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,
                           OSMESA_ACCUM_BITS, 0, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    impl_->ctx = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!impl_->ctx) throw OffscreenError("OSMesa: cannot create an offscreen OpenGL 3.3 core context");
    impl_->buffer.resize(4 * static_cast<size_t>(width) * height);
    if (!OSMesaMakeCurrent(impl_->ctx, impl_->buffer.data(), GL_UNSIGNED_BYTE, width, height)) {
        OSMesaDestroyContext(impl_->ctx);
        throw OffscreenError("OSMesa: cannot make the context current");
    }
    description_ = "OSMesa (" + glRendererName() + ")";
}

OffscreenContext::~OffscreenContext() {
    if (impl_->ctx) OSMesaDestroyContext(impl_->ctx);
}

void OffscreenContext::makeCurrent() {
    OSMesaMakeCurrent(impl_->ctx, impl_->buffer.data(), GL_UNSIGNED_BYTE, width_, height_);
}

Image OffscreenContext::read() {
    glFinish();
    return readPixels(width_, height_);
}

}  // namespace clothlab
