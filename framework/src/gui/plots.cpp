// Line plots with axes drawn through Dear ImGui's draw list.
#include "clothlab/gui/plots.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace clothlab {

std::vector<double> niceTicks(double lo, double hi, int n, bool log) {
    std::vector<double> t;
    if (!(hi > lo)) return t;
    if (log) {  // powers of ten; within less than two decades also 2 and 5 times them, then every digit
        for (const std::vector<double>& ms : {std::vector<double>{1}, {1, 2, 5}, {1, 2, 3, 4, 5, 6, 7, 8, 9}}) {
            t.clear();
            for (double e = std::floor(std::log10(lo)); e <= std::ceil(std::log10(hi)); e += 1)
                for (const double m : ms) {
                    const double v = m * std::pow(10.0, e);
                    if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9)) t.push_back(v);
                }
            if (t.size() >= 3) return t;
        }
        if (t.size() < 2) t = {lo, hi};
        return t;
    }
    const double raw = (hi - lo) / std::max(1, n), p = std::pow(10.0, std::floor(std::log10(raw)));
    double step = 10 * p;
    for (const double m : {1.0, 2.0, 5.0})
        if (m * p >= raw * (1 - 1e-9)) {
            step = m * p;
            break;
        }
    for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step) t.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
    return t;
}

std::string tickLabel(double v, double step) {
    char b[32];
    const double e = std::log10(std::abs(v));
    if (v != 0 && std::abs(e - std::round(e)) < 1e-9 && (e >= 4 || e <= -4)) std::snprintf(b, sizeof b, "1e%d", static_cast<int>(std::round(e)));
    else if (step > 0 && step >= 1e-4 && std::abs(v) < 1e5)  // as many decimals as the step has
        std::snprintf(b, sizeof b, "%.*f", std::max(0, static_cast<int>(std::ceil(-std::log10(step) - 1e-9))), v);
    else std::snprintf(b, sizeof b, "%.3g", v);
    return b;
}

void plotLines(const PlotAxes& axes, const std::vector<PlotLine>& lines, float width, float height) {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float lh = ImGui::GetTextLineHeight();
    const ImU32 ink = IM_COL32(30, 34, 44, 255), grid = IM_COL32(200, 204, 212, 255), faint = IM_COL32(110, 116, 128, 255);
    // Ranges over the finite points (log axes: the positive ones).
    const auto usable = [](double v, bool log) { return std::isfinite(v) && (!log || v > 0); };
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
    for (const PlotLine& l : lines)
        for (size_t k = 0; k < l.x.size() && k < l.y.size(); ++k)
            if (usable(l.x[k], axes.logx) && usable(l.y[k], axes.logy)) {
                x0 = std::min(x0, l.x[k]), x1 = std::max(x1, l.x[k]);
                y0 = std::min(y0, l.y[k]), y1 = std::max(y1, l.y[k]);
            }
    const bool empty = !(x1 >= x0);
    const auto pad = [](double& lo, double& hi, bool log) {
        if (log) {
            double a = std::log10(lo), b = std::log10(hi);
            if (b - a < 1e-9) a -= 0.5, b += 0.5;
            const double m = 0.05 * (b - a);
            lo = std::pow(10.0, a - m), hi = std::pow(10.0, b + m);
        } else {
            if (hi - lo < 1e-12 * std::max(1.0, std::abs(hi))) {
                const double d = lo != 0 ? 0.01 * std::abs(lo) : 1.0;
                lo -= d, hi += d;
            }
            const double m = 0.05 * (hi - lo);
            lo -= m, hi += m;
        }
    };
    if (!empty) pad(x0, x1, axes.logx), pad(y0, y1, axes.logy);
    const std::vector<double> yt = empty ? std::vector<double>{} : niceTicks(y0, y1, std::max(3, static_cast<int>(height / (3 * lh))), axes.logy);
    float ylabel_w = 0;
    const double ystep = !axes.logy && yt.size() > 1 ? yt[1] - yt[0] : 0.0;
    for (double v : yt) ylabel_w = std::max(ylabel_w, ImGui::CalcTextSize(tickLabel(v, ystep).c_str()).x);
    // The frame: title above, tick labels left and below, the x label under them; the y label is in the title line.
    const ImVec2 a(origin.x + ylabel_w + 6, origin.y + lh + 4), b(origin.x + width - 4, origin.y + height - 2 * lh - 6);
    const std::string title = axes.title + (axes.ylabel.empty() ? "" : "   " + axes.ylabel);
    dl->AddText(ImVec2(origin.x, origin.y), ink, title.c_str());
    dl->AddRectFilled(a, b, IM_COL32(255, 255, 255, 255));
    const auto sx = [&](double v) {
        const double u = axes.logx ? (std::log10(v) - std::log10(x0)) / (std::log10(x1) - std::log10(x0)) : (v - x0) / (x1 - x0);
        return static_cast<float>(a.x + u * (b.x - a.x));
    };
    const auto sy = [&](double v) {
        const double u = axes.logy ? (std::log10(v) - std::log10(y0)) / (std::log10(y1) - std::log10(y0)) : (v - y0) / (y1 - y0);
        return static_cast<float>(b.y - u * (b.y - a.y));
    };
    if (!empty) {
        for (double v : yt) {
            const float y = sy(v);
            dl->AddLine(ImVec2(a.x, y), ImVec2(b.x, y), grid);
            const std::string s = tickLabel(v, ystep);
            dl->AddText(ImVec2(a.x - 4 - ImGui::CalcTextSize(s.c_str()).x, y - lh / 2), faint, s.c_str());
        }
        float last_right = -1e9f;
        const std::vector<double> xt = niceTicks(x0, x1, std::max(2, static_cast<int>((b.x - a.x) / 70)), axes.logx);
        const double xstep = !axes.logx && xt.size() > 1 ? xt[1] - xt[0] : 0.0;
        for (double v : xt) {
            const float x = sx(v);
            dl->AddLine(ImVec2(x, a.y), ImVec2(x, b.y), grid);
            const std::string s = tickLabel(v, xstep);
            const float w = ImGui::CalcTextSize(s.c_str()).x, left = std::clamp(x - w / 2, a.x, b.x - w);
            if (left > last_right + 6) dl->AddText(ImVec2(left, b.y + 2), faint, s.c_str()), last_right = left + w;
        }
        dl->PushClipRect(a, b, true);
        for (const PlotLine& l : lines) {
            std::vector<ImVec2> pts;
            const auto flush = [&] {
                if (pts.size() > 1) dl->AddPolyline(pts.data(), static_cast<int>(pts.size()), l.color, 0, 2.0f);
                pts.clear();
            };
            ImVec2 last(-1, -1);
            bool have = false;
            for (size_t k = 0; k < l.x.size() && k < l.y.size(); ++k) {
                if (!usable(l.x[k], axes.logx) || !usable(l.y[k], axes.logy)) {
                    flush();
                    continue;
                }
                last = ImVec2(sx(l.x[k]), sy(l.y[k]));
                have = true;
                pts.push_back(last);
            }
            flush();
            if (axes.mark_last && have) dl->AddCircleFilled(last, 4.0f, l.color);
        }
        dl->PopClipRect();
    } else {
        dl->AddText(ImVec2(a.x + 6, a.y + 4), faint, axes.empty.c_str());
    }
    dl->AddRect(a, b, IM_COL32(150, 156, 168, 255));
    const float xw = ImGui::CalcTextSize(axes.xlabel.c_str()).x;
    dl->AddText(ImVec2(std::max(a.x, (a.x + b.x - xw) / 2), b.y + lh + 4), ink, axes.xlabel.c_str());
    if (axes.legend) {
        float y = a.y + 4, w = 0;
        for (const PlotLine& l : lines) w = std::max(w, ImGui::CalcTextSize(l.label.c_str()).x);
        const float x = b.x - w - 30;
        dl->AddRectFilled(ImVec2(x - 4, y - 2), ImVec2(b.x - 2, y + lines.size() * lh + 2), IM_COL32(255, 255, 255, 220));
        for (const PlotLine& l : lines) {
            dl->AddLine(ImVec2(x, y + lh / 2), ImVec2(x + 18, y + lh / 2), l.color, 3.0f);
            dl->AddText(ImVec2(x + 24, y), ink, l.label.c_str());
            y += lh;
        }
    }
    ImGui::Dummy(ImVec2(width, height));
}

}  // namespace clothlab
