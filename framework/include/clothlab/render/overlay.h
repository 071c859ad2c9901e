/// @file overlay.h
/// @brief 2-D overlay drawn with Dear ImGui on top of a rendered frame: title, time and the colour legend.
#pragma once
#include "clothlab/render/draw_data.h"
#include "clothlab/render/renderer.h"

namespace clothlab {

/// Adds the title line, the simulated time, DrawData::note at the bottom-left and (when edges are shown) the legend of edge colours
/// (by kind, or the strain colour bar) to the current ImGui frame's foreground.
/// Call between ImGui::NewFrame() and ImGui::Render().
/// @param d    what is drawn (title, t, which edge kinds exist)
/// @param opt  render options (edges shown? coloured by strain?)
/// @param left  pixels to keep free on the left (e.g. for the app's panel)
void drawOverlay(const DrawData& d, const RenderOptions& opt, float left = 0.0f);

}  // namespace clothlab
