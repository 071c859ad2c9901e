/// @file plots.h
/// @brief Line plots with axes, ticks, units and a legend, drawn with Dear ImGui's draw list (the
/// app's live plots: one line per run of a comparison).
#pragma once
#include <string>
#include <vector>

namespace clothlab {

/// One line of a plot.
struct PlotLine {
    std::vector<double> x;   ///< abscissae (NaN, and ≤ 0 on a log axis, leave a gap)
    std::vector<double> y;   ///< ordinates, as many as x
    unsigned color = 0;      ///< ImGui colour (IM_COL32)
    std::string label;       ///< legend entry
};

/// The frame of a plot.
struct PlotAxes {
    std::string title;       ///< over the plot, e.g. "energy"
    std::string xlabel;      ///< with its unit, e.g. "t [s]"
    std::string ylabel;      ///< with its unit, e.g. "energy [J]"
    bool logx = false;       ///< logarithmic x axis (decades)
    bool logy = false;       ///< logarithmic y axis (decades)
    bool legend = false;     ///< the lines' labels in the plot's top-right corner
    bool mark_last = false;  ///< a dot on each line's last point (the run's "now")
    std::string empty = "no samples yet";  ///< shown when no line has a point to draw
};

/// Tick positions between lo and hi: on a linear axis multiples of 1, 2 or 5 × 10^k, about `n` of them,
/// \f$ \Delta = \min\{ m\,10^k \ge (hi - lo)/n : m \in \{1, 2, 5\} \} \f$; on a log axis the powers of
/// ten in [lo, hi] (both > 0), with fewer than three of them also 2 and 5 times the powers of ten, then
/// every digit times them, and lo and hi when fewer than two such ticks lie between them.
/// @param lo, hi  the axis range (lo < hi)
/// @param n       about how many ticks
/// @param log     logarithmic axis
std::vector<double> niceTicks(double lo, double hi, int n, bool log);

/// A tick's label: a power of ten below 1e-3 or from 1e4 up as "1e-4"; on a linear axis with the decimals
/// of its step (step 0.005: "4.855"); else three significant digits.
/// @param v     the tick value
/// @param step  the distance between ticks on a linear axis (0: a log axis)
std::string tickLabel(double v, double step);

/// Draws a plot at the current ImGui cursor, `width` x `height` pixels including its title, tick labels
/// and axis labels: the range of every line's finite points (padded by 5 %, a flat line by ±1 % or ±1),
/// grid lines at niceTicks(), the lines, and (PlotAxes) the legend and a dot at each line's last point.
/// Call inside an ImGui window.
/// @param axes    title, labels, log axes, legend
/// @param lines   the lines
/// @param width   pixels
/// @param height  pixels
void plotLines(const PlotAxes& axes, const std::vector<PlotLine>& lines, float width, float height);

}  // namespace clothlab
