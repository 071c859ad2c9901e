// Dear ImGui's renderer backend on OpenGL 3.3 core / WebGL2 (imgui_gl.h), with the renderer's shader
// version switch (gl.h).
#include "clothlab/render/imgui_gl.h"

#include <imgui.h>

#include <cstdint>

#include "gl.h"

namespace clothlab {

namespace {

const char* const kVertexShader = R"(
in vec2 aPosition;
in vec2 aUv;
in vec4 aColor;
uniform mat4 uProjection;
out vec2 vUv;
out vec4 vColor;
void main() {
    vUv = aUv;
    vColor = aColor;
    gl_Position = uProjection * vec4(aPosition, 0.0, 1.0);
}
)";
const char* const kFragmentShader = R"(
in vec2 vUv;
in vec4 vColor;
uniform sampler2D uTexture;
out vec4 fragColor;
void main() {
    fragColor = vColor * texture(uTexture, vUv);
}
)";
const char* const kAttributes[] = {"aPosition", "aUv", "aColor"};

// The GL objects of one ImGui context (its IO's BackendRendererUserData).
struct Backend {
    GLuint program = 0, vao = 0, font = 0;
    GLint uProjection = -1, uTexture = -1;
    gl::Buffer vertices, indices;
};

Backend* backend() { return ImGui::GetCurrentContext() ? static_cast<Backend*>(ImGui::GetIO().BackendRendererUserData) : nullptr; }

}  // namespace

void imguiGlInit() {
    ImGuiIO& io = ImGui::GetIO();
    io.BackendRendererUserData = new Backend;
    io.BackendRendererName = "clothlab_gl";
}

void imguiGlNewFrame() {
    Backend* b = backend();
    if (!b || b->program) return;
    b->program = gl::program(kVertexShader, kFragmentShader, kAttributes, 3);
    b->uProjection = glGetUniformLocation(b->program, "uProjection");
    b->uTexture = glGetUniformLocation(b->program, "uTexture");
    glGenVertexArrays(1, &b->vao);
    glBindVertexArray(b->vao);
    b->vertices.upload(GL_ARRAY_BUFFER, nullptr, 0);  // creates and binds the buffers: the vertex array keeps them
    b->indices.upload(GL_ELEMENT_ARRAY_BUFFER, nullptr, 0);
    const auto at = [](size_t offset) { return reinterpret_cast<const void*>(offset); };
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(ImDrawVert), at(offsetof(ImDrawVert, pos)));
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, sizeof(ImDrawVert), at(offsetof(ImDrawVert, uv)));
    glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(ImDrawVert), at(offsetof(ImDrawVert, col)));
    for (GLuint a = 0; a < 3; ++a) glEnableVertexAttribArray(a);
    glBindVertexArray(0);

    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    glGenTextures(1, &b->font);
    glBindTexture(GL_TEXTURE_2D, b->font);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    ImGui::GetIO().Fonts->SetTexID(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(b->font)));
}

void imguiGlRender(ImDrawData* data) {
    Backend* b = backend();
    const int fb_w = static_cast<int>(data->DisplaySize.x * data->FramebufferScale.x);
    const int fb_h = static_cast<int>(data->DisplaySize.y * data->FramebufferScale.y);
    if (!b || !b->program || fb_w <= 0 || fb_h <= 0) return;
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_SCISSOR_TEST);
    glViewport(0, 0, fb_w, fb_h);
    // Orthographic: the display rectangle onto [-1, 1]^2, y down.
    const float l = data->DisplayPos.x, r = l + data->DisplaySize.x, t = data->DisplayPos.y, bt = t + data->DisplaySize.y;
    const float ortho[16] = {2 / (r - l), 0, 0, 0, 0, 2 / (t - bt), 0, 0, 0, 0, -1, 0, (r + l) / (l - r), (t + bt) / (bt - t), 0, 1};
    glUseProgram(b->program);
    glUniformMatrix4fv(b->uProjection, 1, GL_FALSE, ortho);
    glUniform1i(b->uTexture, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(b->vao);
    const ImVec2 off = data->DisplayPos, sc = data->FramebufferScale;
    for (int n = 0; n < data->CmdListsCount; ++n) {
        const ImDrawList* list = data->CmdLists[n];
        b->vertices.upload(GL_ARRAY_BUFFER, list->VtxBuffer.Data, static_cast<long>(list->VtxBuffer.Size * sizeof(ImDrawVert)));
        b->indices.upload(GL_ELEMENT_ARRAY_BUFFER, list->IdxBuffer.Data, static_cast<long>(list->IdxBuffer.Size * sizeof(ImDrawIdx)));
        for (const ImDrawCmd& cmd : list->CmdBuffer) {
            if (cmd.UserCallback) {
                if (cmd.UserCallback != ImDrawCallback_ResetRenderState) cmd.UserCallback(list, &cmd);
                continue;
            }
            const float x0 = (cmd.ClipRect.x - off.x) * sc.x, y0 = (cmd.ClipRect.y - off.y) * sc.y;
            const float x1 = (cmd.ClipRect.z - off.x) * sc.x, y1 = (cmd.ClipRect.w - off.y) * sc.y;
            if (x1 <= x0 || y1 <= y0) continue;
            glScissor(static_cast<int>(x0), static_cast<int>(fb_h - y1), static_cast<int>(x1 - x0), static_cast<int>(y1 - y0));
            glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(reinterpret_cast<intptr_t>(cmd.GetTexID())));
            glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(cmd.ElemCount), sizeof(ImDrawIdx) == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(cmd.IdxOffset * sizeof(ImDrawIdx)));
        }
    }
    glBindVertexArray(0);
    glUseProgram(0);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glFlush();  // llvmpipe rasterizes on its own threads from here, while the caller waits for the stepping (App::endFrame())
}

void imguiGlShutdown() {
    Backend* b = backend();
    if (!b) return;
    if (b->program) {
        glDeleteProgram(b->program);
        glDeleteVertexArrays(1, &b->vao);
        glDeleteTextures(1, &b->font);
        glDeleteBuffers(1, &b->vertices.id);
        glDeleteBuffers(1, &b->indices.id);
    }
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->SetTexID(nullptr);
    io.BackendRendererUserData = nullptr;
    io.BackendRendererName = nullptr;
    delete b;
}

}  // namespace clothlab
