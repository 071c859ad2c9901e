// The offscreen context through EGL without a window (linked only into clothlab-render-egl and the
// EGL render tests; offscreen_osmesa.cpp is the other implementation of offscreen.h). For Mesa
// after OSMesa (removed in Mesa 25.1): an OpenGL 3.3 core-profile context on Mesa's surfaceless
// platform (EGL_MESA_platform_surfaceless), or else on the first EGL device (EGL_EXT_platform_device).
// Neither has a default framebuffer, so the context draws into a framebuffer object (RGBA8 colour,
// 24-bit depth, 8-bit stencil) that read() reads back like OSMesa's buffer.
#include "clothlab/render/offscreen.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#define GL_GLEXT_PROTOTYPES 1  // glGenFramebuffers & co. (OpenGL 3.0), exported by libOpenGL
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdio>
#include <string>

#include "clothlab/render/renderer.h"

namespace clothlab {

namespace {

// "eglInitialize failed (EGL_NOT_INITIALIZED)": the call and eglGetError()'s name.
std::string eglFailure(const char* call) {
    const EGLint e = eglGetError();
    const char* name = e == EGL_NOT_INITIALIZED ? "EGL_NOT_INITIALIZED"
                     : e == EGL_BAD_ALLOC       ? "EGL_BAD_ALLOC"
                     : e == EGL_BAD_ATTRIBUTE   ? "EGL_BAD_ATTRIBUTE"
                     : e == EGL_BAD_CONFIG      ? "EGL_BAD_CONFIG"
                     : e == EGL_BAD_DISPLAY     ? "EGL_BAD_DISPLAY"
                     : e == EGL_BAD_MATCH       ? "EGL_BAD_MATCH"
                     : e == EGL_BAD_PARAMETER   ? "EGL_BAD_PARAMETER"
                     : nullptr;
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(e));
    return std::string("EGL: ") + call + " failed (" + (name ? name : code) + ")";
}

bool hasExtension(const char* list, const std::string& ext) {
    const std::string all = std::string(" ") + (list ? list : "") + " ";
    return all.find(" " + ext + " ") != std::string::npos;
}

// An initialised display on the surfaceless platform, or else on the first device; `platform` names it.
EGLDisplay openDisplay(std::string& platform) {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);  // null without EGL_EXT_client_extensions
    auto getDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getDisplay) throw OffscreenError("EGL: no eglGetPlatformDisplayEXT (EGL_EXT_platform_base)");
    EGLint major = 0, minor = 0;
    std::string surfaceless_failed;  // why the surfaceless platform, offered, did not work
    if (hasExtension(client, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d = getDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) return platform = "surfaceless", d;
        surfaceless_failed = eglFailure("eglInitialize on the surfaceless platform");
    }
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    EGLDeviceEXT device = nullptr;
    EGLint devices = 0;
    if (hasExtension(client, "EGL_EXT_platform_device") && queryDevices && queryDevices(1, &device, &devices) && devices > 0) {
        EGLDisplay d = getDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
        if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) return platform = "device", d;
        throw OffscreenError(eglFailure("eglInitialize on the first EGL device"));
    }
    if (!surfaceless_failed.empty()) throw OffscreenError(surfaceless_failed);
    throw OffscreenError("EGL: neither the surfaceless platform (EGL_MESA_platform_surfaceless) nor an EGL device "
                         "(EGL_EXT_platform_device) is available (is libegl-mesa0 installed?)");
}

}  // namespace

struct OffscreenContext::Impl {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    GLuint framebuffer = 0, colour = 0, depth = 0;  // the framebuffer object and its two renderbuffers
};

OffscreenContext::OffscreenContext(int width, int height) : impl_(std::make_unique<Impl>()), width_(width), height_(height) {
    Impl& m = *impl_;
    std::string platform;
    m.display = openDisplay(platform);
    auto fail = [&](const std::string& what) {
        if (m.context != EGL_NO_CONTEXT) eglDestroyContext(m.display, m.context);
        throw OffscreenError(what);
    };
    if (!eglBindAPI(EGL_OPENGL_API)) fail(eglFailure("eglBindAPI(EGL_OPENGL_API)"));
    // Any config that can render desktop OpenGL (the framebuffer object sets the real formats); without
    // one, a context without a config (EGL_KHR_no_config_context).
    const EGLint want[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    if (!eglChooseConfig(m.display, want, &config, 1, &configs) || configs < 1) config = EGL_NO_CONFIG_KHR;
    // OpenGL 3.3 core profile, what the renderer and its ImGui backend are written for.
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    m.context = eglCreateContext(m.display, config, EGL_NO_CONTEXT, attribs);
    if (m.context == EGL_NO_CONTEXT) fail(eglFailure("eglCreateContext (OpenGL 3.3, core profile)"));
    if (!eglMakeCurrent(m.display, EGL_NO_SURFACE, EGL_NO_SURFACE, m.context))
        fail(eglFailure("eglMakeCurrent without a surface (EGL_KHR_surfaceless_context)"));

    glGenFramebuffers(1, &m.framebuffer);
    glGenRenderbuffers(1, &m.colour);
    glGenRenderbuffers(1, &m.depth);
    glBindRenderbuffer(GL_RENDERBUFFER, m.colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, m.depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, m.framebuffer);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m.colour);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, m.depth);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        char code[16];
        std::snprintf(code, sizeof code, "0x%04x", status);
        fail(std::string("EGL: the framebuffer object is incomplete (status ") + code + ")");
    }
    glViewport(0, 0, width, height);
    description_ = "EGL " + platform + " (" + glRendererName() + ")";
}

OffscreenContext::~OffscreenContext() {
    Impl& m = *impl_;
    if (eglMakeCurrent(m.display, EGL_NO_SURFACE, EGL_NO_SURFACE, m.context)) {
        glDeleteFramebuffers(1, &m.framebuffer);
        glDeleteRenderbuffers(1, &m.colour);
        glDeleteRenderbuffers(1, &m.depth);
    }
    eglMakeCurrent(m.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(m.display, m.context);
    // No eglTerminate: the display is one per process, and another context (a test's) may still use it.
}

void OffscreenContext::makeCurrent() {
    eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, impl_->context);
    glBindFramebuffer(GL_FRAMEBUFFER, impl_->framebuffer);
}

Image OffscreenContext::read() {
    glFinish();
    glBindFramebuffer(GL_READ_FRAMEBUFFER, impl_->framebuffer);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    return readPixels(width_, height_);
}

}  // namespace clothlab
