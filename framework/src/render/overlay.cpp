// Title, time and colour legend drawn with Dear ImGui's foreground draw list.
#include "clothlab/render/overlay.h"

#include <imgui.h>

#include <cstdio>

namespace clothlab {

namespace {
ImU32 rgb(const Eigen::Vector3f& c, float a = 1.0f) { return ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], a)); }
}  // namespace

void drawOverlay(const DrawData& d, const RenderOptions& opt, float left) {
    if (!opt.legend) return;
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    const ImU32 ink = IM_COL32(30, 34, 44, 255);
    char line[96];
    std::snprintf(line, sizeof line, "t = %.3f s", d.t);
    dl->AddText(ImVec2(left + 10, 8), ink, d.title.c_str());
    dl->AddText(ImVec2(left + 10, 8 + ImGui::GetTextLineHeightWithSpacing()), ink, line);

    const bool edges_shown = opt.edges || d.triangles.empty();
    const float lh = ImGui::GetTextLineHeightWithSpacing();
    if (!d.note.empty()) {
        const ImVec2 q(left + 10, size.y - lh - 8), w = ImGui::CalcTextSize(d.note.c_str());
        dl->AddRectFilled(ImVec2(q.x - 4, q.y - 3), ImVec2(q.x + w.x + 4, q.y + w.y + 3), IM_COL32(255, 255, 255, 200), 4);
        dl->AddText(q, ink, d.note.c_str());
    }
    if (!d.ghosts.empty()) {
        // Legend of the two spheres: simulated particle and analytic solution.
        const ImVec2 q(left + 10, size.y - 2 * lh - 8);
        dl->AddRectFilled(ImVec2(q.x - 4, q.y - 4), ImVec2(q.x + 190, size.y - 4), IM_COL32(255, 255, 255, 200), 4);
        dl->AddCircleFilled(ImVec2(q.x + 8, q.y + lh / 2), 6, IM_COL32(242, 140, 38, 255));
        dl->AddText(ImVec2(q.x + 20, q.y), ink, "simulated");
        dl->AddCircle(ImVec2(q.x + 8, q.y + lh * 1.5f), 7, IM_COL32(26, 178, 64, 230), 24, 2.5f);
        dl->AddText(ImVec2(q.x + 20, q.y + lh), ink, "analytic solution");
    }
    if (!edges_shown || d.edges.empty()) return;
    ImVec2 p(size.x - 170, size.y - 10);
    if (opt.color_by_strain) {
        // A vertical colour bar from -range (blue) to +range (red).
        const float h = 120, w = 14;
        p = ImVec2(size.x - 130, size.y - h - 24);
        dl->AddRectFilled(ImVec2(p.x - 8, p.y - 2 * lh - 4), ImVec2(size.x - 8, size.y - 6), IM_COL32(255, 255, 255, 200), 4);
        dl->AddText(ImVec2(p.x, p.y - 2 * lh), ink, "strain l/l0 - 1");
        const int steps = 24;
        for (int k = 0; k < steps; ++k) {
            const double s0 = opt.strain_range * (1 - 2.0 * k / steps), s1 = opt.strain_range * (1 - 2.0 * (k + 1) / steps);
            dl->AddRectFilledMultiColor(ImVec2(p.x, p.y + h * k / steps), ImVec2(p.x + w, p.y + h * (k + 1) / steps),
                                        rgb(strainColor(s0, opt.strain_range)), rgb(strainColor(s0, opt.strain_range)),
                                        rgb(strainColor(s1, opt.strain_range)), rgb(strainColor(s1, opt.strain_range)));
        }
        for (int k = 0; k <= 2; ++k) {
            std::snprintf(line, sizeof line, "%+.0f %%", 100 * opt.strain_range * (1 - k));
            dl->AddText(ImVec2(p.x + w + 6, p.y + h * k / 2 - lh / 2), ink, line);
        }
        return;
    }
    bool present[4] = {false, false, false, false};
    for (EdgeKind k : d.edge_kind) present[static_cast<int>(k)] = true;
    int rows = 0;
    for (int k = 0; k < 4; ++k) rows += present[k] && opt.show_kind[k];
    if (!rows) return;
    p = ImVec2(size.x - 130, size.y - 8 - rows * lh);
    dl->AddRectFilled(ImVec2(p.x - 8, p.y - 6), ImVec2(size.x - 8, size.y - 4), IM_COL32(255, 255, 255, 200), 4);
    for (int k = 0; k < 4; ++k) {
        if (!present[k] || !opt.show_kind[k]) continue;
        const Eigen::Vector3f c = edgeKindColor(static_cast<EdgeKind>(k));
        dl->AddLine(ImVec2(p.x, p.y + lh / 2), ImVec2(p.x + 24, p.y + lh / 2), rgb(c), 3.0f);
        dl->AddText(ImVec2(p.x + 30, p.y), ink, edgeKindName(static_cast<EdgeKind>(k)));
        p.y += lh;
    }
}

}  // namespace clothlab
