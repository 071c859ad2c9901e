/// @file imgui_gl.h
/// @brief Dear ImGui's renderer backend on the renderer's OpenGL: OpenGL 3.3 core, or WebGL2 in the
/// browser build, with the same shader source and version switch as the renderer (framework/src/render/gl.h).
///
/// Used in place of ImGui's own OpenGL backends by every program (offscreen, window, browser): Debian's
/// compiled OpenGL3 backend loads libGL.so.1 itself, which does not reach an OSMesa context.
/// Call order per ImGui context: imguiGlInit(), then each frame imguiGlNewFrame() before
/// ImGui::NewFrame() and imguiGlRender() after ImGui::Render(), and imguiGlShutdown() at the end.
#pragma once

struct ImDrawData;

namespace clothlab {

/// Makes the current ImGui context draw with this backend in the current GL context (sets the IO's
/// backend name and flags; the GL objects are made by the first imguiGlNewFrame()).
void imguiGlInit();

/// Makes the GL objects if not made yet (shader program, vertex array, buffers, the font atlas'
/// texture); call before ImGui::NewFrame(), which needs the font atlas built.
void imguiGlNewFrame();

/// Draws the frame's draw lists into the current framebuffer (blended, clipped to each command's
/// rectangle); leaves blending, the scissor test and the program off. Ends with glFlush(), not
/// glFinish(): the GL may still be drawing when it returns.
/// @param data  ImGui::GetDrawData() after ImGui::Render()
void imguiGlRender(ImDrawData* data);

/// Deletes the GL objects (the GL context must still be current) and detaches the backend from the
/// ImGui context.
void imguiGlShutdown();

}  // namespace clothlab
