// `clothlab study sag`: the static sag of a hanging cloth against the iterations, PBD vs XPBD.
#include "clothlab/study/sag.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "clothlab/io/scene_json.h"
#include "clothlab/sim/run.h"
#include "clothlab/sim/simulation.h"
#include "clothlab/study/plot.h"

namespace clothlab {
namespace {

/// The sag of one run: the drop of the lowest particle after `seconds` (NaN if the run was unstable).
double sagOf(const std::string& file, std::vector<std::string> sets, double seconds) {
    auto sim = makeSimulation(loadScene(file, sets));
    const double start = sim->state().x.row(1).minCoeff();
    const long long steps = std::llround(seconds / sim->scene().solver.dt);
    if (runSimulation(*sim, steps, steps).unstable) return std::numeric_limits<double>::quiet_NaN();
    return start - sim->state().x.row(1).minCoeff();
}

std::string num(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

}  // namespace

SagResult sagStudy(const std::string& scene_file, const std::vector<std::string>& overrides, const SagOptions& o) {
    SagResult r;
    r.scene = r.file = scene_file;
    for (const std::string& s : overrides) r.scene += " --set " + s;
    r.iterations = o.iterations;
    r.seconds = o.seconds;
    const double k = loadScene(scene_file, overrides).constraints.distance.stiffness;
    // Each series: a label and the overrides that make it (the iteration count is added per run).
    std::vector<std::pair<std::string, std::vector<std::string>>> series = {
        {"PBD, k = " + num(k), {"solver.method=pbd", "solver.substeps=1"}}};
    for (int sub : o.xpbd_substeps)
        series.push_back({"XPBD, alpha = " + num(o.compliance) + " m/N, " + std::to_string(sub) + (sub == 1 ? " substep" : " substeps"),
                          {"solver.method=xpbd", "constraints.distance.compliance=" + num(o.compliance),
                           "solver.substeps=" + std::to_string(sub)}});
    for (const auto& [label, sets] : series) {
        SagSeries s{label, {}};
        for (int it : o.iterations) {
            std::vector<std::string> all = overrides;
            all.insert(all.end(), sets.begin(), sets.end());
            all.push_back("solver.iterations=" + std::to_string(it));
            s.sag.push_back(sagOf(scene_file, all, o.seconds));
        }
        r.series.push_back(s);
    }
    return r;
}

void printSagTable(std::ostream& out, const SagResult& r) {
    out << "static sag after " << r.seconds << " s [mm]: " << r.scene << "\n";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%10s", "iterations");
    out << buf;
    for (const SagSeries& s : r.series) out << " | " << s.label;
    out << "\n";
    for (size_t i = 0; i < r.iterations.size(); ++i) {
        std::snprintf(buf, sizeof buf, "%10d", r.iterations[i]);
        out << buf;
        for (const SagSeries& s : r.series) {
            if (std::isfinite(s.sag[i])) std::snprintf(buf, sizeof buf, " | %*.3f", static_cast<int>(s.label.size()), 1e3 * s.sag[i]);
            else std::snprintf(buf, sizeof buf, " | %*s", static_cast<int>(s.label.size()), "unstable");  // the run stopped (run.h)
            out << buf;
        }
        out << "\n";
    }
}

std::vector<std::string> writeSag(const std::string& dir, const SagResult& r) {
    std::vector<std::string> written;
    {
        std::ofstream csv(dir + "/sag.csv");
        csv << "iterations";
        for (const SagSeries& s : r.series) csv << ",\"" << s.label << "\"";
        csv << "\n";
        csv.precision(9);
        for (size_t i = 0; i < r.iterations.size(); ++i) {
            csv << r.iterations[i];
            for (const SagSeries& s : r.series) csv << "," << s.sag[i];
            csv << "\n";
        }
    }
    written.push_back(dir + "/sag.csv");
    std::ostringstream g;
    g << "cd '" << dir << "'\nset terminal pngcairo size 900,620 font ',11'\nset output 'sag.png'\n"
      << "set datafile separator ','\nset logscale xy\nset grid\nset key below vertical noenhanced\n"
      << "set title \"static sag after " << r.seconds << " s: " << r.file << "\" noenhanced\n"
      << "set xlabel 'solver iterations per step'\nset ylabel 'sag [m]'\nplot";
    for (size_t c = 0; c < r.series.size(); ++c)
        g << (c ? ", \\\n    " : " ") << "'sag.csv' using 1:" << c + 2 << " every ::1 with linespoints lw 2 pt " << 7 + 2 * c
          << " title '" << r.series[c].label << "'";
    g << "\n";
    if (runGnuplot(dir + "/sag.gp", g.str())) written.push_back(dir + "/sag.png");
    return written;
}

}  // namespace clothlab
