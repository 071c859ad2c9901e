// The one build switch between the two OpenGL dialects the renderer runs on (framework/src/render):
//   desktop: OpenGL 3.3 core profile (OSMesa, EGL, a GLFW window), shaders in GLSL 3.30;
//   browser (CLOTHLAB_WEB, set by cmake/web.cmake): WebGL2 = OpenGL ES 3.0, shaders in GLSL ES 3.00.
// The renderer's and ImGui's shaders are written once and start with kGlslHeader; everything else
// (calls, buffers, state) is the common subset of the two.
#pragma once

#ifdef CLOTHLAB_WEB
#include <GLES3/gl3.h>
#define CLOTHLAB_GL_DESKTOP 0
#else
#define GL_GLEXT_PROTOTYPES 1  // the OpenGL 2.0-3.3 functions, exported by libOSMesa, libOpenGL and libGL
#include <GL/gl.h>
#include <GL/glext.h>
#define CLOTHLAB_GL_DESKTOP 1
#endif

namespace clothlab::gl {

/// The first lines of every shader: the GLSL version (and for GLSL ES the default float precision).
#if CLOTHLAB_GL_DESKTOP
inline constexpr const char* kGlslHeader = "#version 330 core\n";
#else
inline constexpr const char* kGlslHeader = "#version 300 es\nprecision highp float;\n";
#endif

/// Compiles and links a program from a vertex and a fragment shader's bodies (kGlslHeader, then
/// `defines`, put in front of each), with the vertex attributes bound to the locations given by
/// `attributes` (its index).
/// @throws std::runtime_error with the compiler's log when a shader does not compile or link
unsigned program(const char* vertex, const char* fragment, const char* const* attributes, int n_attributes,
                 const char* defines = "");

/// A growing buffer object: the first upload of a size allocates it (glBufferData, a little larger),
/// later ones of up to that size only replace its contents (glBufferSubData).
struct Buffer {
    unsigned id = 0;         ///< the buffer object (0: not created yet)
    long capacity = 0;       ///< allocated bytes
    /// Uploads `bytes` bytes to the buffer bound to `target` (bound here).
    /// @param target  GL_ARRAY_BUFFER or GL_ELEMENT_ARRAY_BUFFER
    /// @param data    the bytes
    /// @param bytes   how many
    void upload(unsigned target, const void* data, long bytes);
};

}  // namespace clothlab::gl
