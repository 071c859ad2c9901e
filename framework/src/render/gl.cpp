// Shader programs and buffer objects, for the renderer and the ImGui backend (gl.h).
#include "gl.h"

#include <stdexcept>
#include <string>

namespace clothlab::gl {

namespace {
unsigned compile(GLenum kind, const char* defines, const char* body) {
    const GLuint s = glCreateShader(kind);
    const char* parts[3] = {kGlslHeader, defines, body};
    glShaderSource(s, 3, parts, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = "";
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        glDeleteShader(s);
        throw std::runtime_error(std::string("renderer: a ") + (kind == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                                 " shader does not compile: " + log);
    }
    return s;
}
}  // namespace

unsigned program(const char* vertex, const char* fragment, const char* const* attributes, int n_attributes,
                 const char* defines) {
    const GLuint vs = compile(GL_VERTEX_SHADER, defines, vertex), fs = compile(GL_FRAGMENT_SHADER, defines, fragment);
    const GLuint p = glCreateProgram();
    glAttachShader(p, vs);
    glAttachShader(p, fs);
    for (int i = 0; i < n_attributes; ++i) glBindAttribLocation(p, static_cast<GLuint>(i), attributes[i]);
    glLinkProgram(p);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048] = "";
        glGetProgramInfoLog(p, sizeof log, nullptr, log);
        glDeleteProgram(p);
        throw std::runtime_error(std::string("renderer: a shader program does not link: ") + log);
    }
    return p;
}

void Buffer::upload(unsigned target, const void* data, long bytes) {
    if (id == 0) glGenBuffers(1, &id);
    glBindBuffer(target, id);
    if (bytes > capacity) {
        capacity = bytes + bytes / 2 + 256;
        glBufferData(target, capacity, nullptr, GL_DYNAMIC_DRAW);
    }
    if (bytes > 0) glBufferSubData(target, 0, bytes, data);
}

}  // namespace clothlab::gl
