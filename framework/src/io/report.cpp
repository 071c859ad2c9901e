#include "clothlab/io/report.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "clothlab/core/input_error.h"
#include "clothlab/sim/scene_checks.h"

namespace clothlab {
namespace {
std::ofstream openForWriting(const std::string& path) {
    std::ofstream out(path);
    if (!out) throw InputError(path, "(file)", "cannot write the file");
    out << std::setprecision(std::numeric_limits<double>::max_digits10);  // 17: doubles read back bit for bit
    return out;
}
std::string label(const Metric& m) { return m.name + " [" + m.unit + "]"; }
}  // namespace

void printReportHeader(std::ostream& out, const ReportRow& first) {
    out << std::setw(10) << "step" << std::setw(12) << "t [s]" << std::setw(12) << "wall [s]";
    for (const Metric& m : first.metrics) out << std::setw(20) << label(m);
    out << "\n";
}

void printReportRow(std::ostream& out, const ReportRow& row) {
    char buf[64];
    out << std::setw(10) << row.step;
    std::snprintf(buf, sizeof buf, "%12.4f%12.4f", row.t, row.wall);
    out << buf;
    for (const Metric& m : row.metrics) {
        std::snprintf(buf, sizeof buf, "%20.6e", m.value);
        out << buf;
    }
    out << "\n";
}

void printSummary(std::ostream& out, const Simulation& sim, const RunResult& r) {
    char buf[256];
    const double per_step = r.steps > 0 ? r.wall / static_cast<double>(r.steps) : 0.0;
    std::snprintf(buf, sizeof buf, "summary: %lld steps, %.4g s simulated in %.4g s wall (%.3g us per step)\n",
                  r.steps, sim.state().t, r.wall, per_step * 1e6);
    out << buf;
    if (r.unstable && !r.rows.empty())
        out << "  (stopped early, at step " << r.steps << ": the metrics below are of the last report row, step " << r.rows.back().step << ")\n";
    if (!r.rows.empty())
        for (const Metric& m : r.rows.back().metrics) {
            std::snprintf(buf, sizeof buf, "  %-22s %14.6e %s\n", m.name.c_str(), m.value, m.unit.c_str());
            out << buf;
        }
    if (!sim.scene().colliders.empty()) {
        std::snprintf(buf, sizeof buf, "  %-22s %14.6e %s (over the whole run, at step %lld)\n", "worst_penetration", r.worst_penetration,
                      "m", r.worst_penetration_step);
        out << buf;
    }
    const LookChecks look = lookChecks(sim);  // what the picture shows, at the end (sim/scene_checks.h)
    if (look.through_applies) {
        std::snprintf(buf, sizeof buf, "  %-22s %14d of %d cloth triangles through a collider's surface (at the end)\n", "triangles_through",
                      look.through, look.triangles);
        out << buf;
    }
    if (look.flips_applies) {
        std::snprintf(buf, sizeof buf, "  %-22s %14d of %d cloth triangles turned against the rest shape's normal (at the end)\n",
                      "turned_over", look.flips.flipped, look.flips.triangles);
        out << buf;
    }
    if (r.windowed) {
        std::snprintf(buf, sizeof buf, "over t in [%.6g, %.6g] s (%lld states, --window):\n", r.window.from, r.window.to, r.window_states);
        out << buf;
        std::snprintf(buf, sizeof buf, "  %-22s %14s %14s %14s\n", "", "min", "mean", "max");
        out << buf;
        for (const WindowStat& w : r.window_stats) {
            std::snprintf(buf, sizeof buf, "  %-22s %14.6e %14.6e %14.6e %s\n", w.name.c_str(), w.min, w.mean, w.max, w.unit.c_str());
            out << buf;
        }
    }
    if (!r.warnings.empty()) {
        out << "warnings (" << r.warnings.size() << "): do not trust the numbers above; each warning says why and what would help\n";
        for (const RunWarning& w : r.warnings) out << "  warning: " << warningText(w, sim.scene()) << "\n";
    }
    for (const std::string& n : r.notes) out << "note: " << n << "\n";
    double total = 0.0;
    for (const auto& p : sim.timer().passes()) total += p.seconds;
    out << "passes that ran (wall time):\n";
    for (const auto& p : sim.timer().passes()) {
        std::snprintf(buf, sizeof buf, "  %-34s %10.4f s %10lld calls %6.1f %%\n", p.name.c_str(), p.seconds, p.calls,
                      total > 0 ? 100.0 * p.seconds / total : 0.0);
        out << buf;
    }
}

void writeReportCsv(const std::string& path, const RunResult& r) {
    std::ofstream out = openForWriting(path);
    out << "step,t [s],wall [s]";
    if (!r.rows.empty())
        for (const Metric& m : r.rows.front().metrics) out << "," << label(m);
    out << "\n";
    for (const ReportRow& row : r.rows) {
        out << row.step << "," << row.t << "," << row.wall;
        for (const Metric& m : row.metrics) out << "," << m.value;
        out << "\n";
    }
}

void writeSummaryJson(const std::string& path, const Simulation& sim, const RunResult& r) {
    nlohmann::json j;
    j["scene"] = sim.scene().file;
    j["method"] = methodName(sim.scene().solver.method);
    j["dt"] = sim.scene().solver.dt;
    j["particles"] = sim.state().size();
    j["steps"] = r.steps;
    j["simulated_time"] = sim.state().t;
    j["wall_time"] = r.wall;
    j["unstable"] = r.unstable;
    j["cause"] = causeName(r.cause);
    if (r.unstable) j["message"] = r.message;
    j["metrics"] = nlohmann::json::object();
    if (!r.rows.empty())
        for (const Metric& m : r.rows.back().metrics) j["metrics"][m.name] = {{"value", m.value}, {"unit", m.unit}};
    if (!sim.scene().colliders.empty())
        j["metrics"]["worst_penetration"] = {{"value", r.worst_penetration}, {"unit", "m"}, {"step", r.worst_penetration_step}};
    if (r.windowed) {
        nlohmann::json w = {{"from", r.window.from}, {"to", r.window.to}, {"states", r.window_states}, {"metrics", nlohmann::json::object()}};
        for (const WindowStat& s : r.window_stats) w["metrics"][s.name] = {{"min", s.min}, {"mean", s.mean}, {"max", s.max}, {"unit", s.unit}};
        j["window"] = w;
    }
    const LookChecks look = lookChecks(sim);
    if (look.through_applies) j["metrics"]["triangles_through"] = {{"value", look.through}, {"unit", "1"}, {"of", look.triangles}};
    if (look.flips_applies) j["metrics"]["turned_over"] = {{"value", look.flips.flipped}, {"unit", "1"}, {"of", look.flips.triangles}};
    j["notes"] = r.notes;
    j["warnings"] = nlohmann::json::array();
    for (const RunWarning& w : r.warnings) {
        nlohmann::json x = {{"kind", warningName(w.kind)}, {"step", w.step}, {"t", w.t}, {"value", w.value}, {"message", warningText(w, sim.scene())}};
        if (w.collider >= 0) x["collider"] = w.collider, x["particle"] = w.particle, x["particles"] = w.count;
        if (w.kind == WarningKind::PinMoved) x["particle"] = w.particle, x["particles"] = w.count;
        if (!w.pass.empty()) x["pass"] = w.pass;
        j["warnings"].push_back(x);
    }
    j["passes"] = nlohmann::json::array();
    for (const auto& p : sim.timer().passes())
        j["passes"].push_back({{"name", p.name}, {"seconds", p.seconds}, {"calls", p.calls}});
    std::ofstream out = openForWriting(path);
    out << j.dump(2) << "\n";
}

void writeStateCsv(const std::string& path, const State& s) {
    std::ofstream out = openForWriting(path);
    out << "i,x,y,z,vx,vy,vz\n";
    for (int i = 0; i < s.size(); ++i)
        out << i << "," << s.x(0, i) << "," << s.x(1, i) << "," << s.x(2, i) << "," << s.v(0, i) << ","
            << s.v(1, i) << "," << s.v(2, i) << "\n";
}

void readStateCsv(const std::string& path, State& state) {
    std::ifstream in(path);
    if (!in) throw InputError(path, "(file)", "cannot open the file");
    std::string line;
    if (!std::getline(in, line) || (line != "i,x,y,z,vx,vy,vz" && line != "i,x,y,z,vx,vy,vz\r"))
        throw InputError(path, "(header)", "expected the first line \"i,x,y,z,vx,vy,vz\" (a file from --dump or state.csv)");
    int row = 0;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) continue;
        const std::string where = "row " + std::to_string(row + 2);
        if (row >= state.size())
            throw InputError(path, where, "more rows than the scene has particles (" + std::to_string(state.size()) + ")");
        double v[7];
        std::istringstream fields(line);
        std::string field, index;
        for (int k = 0; k < 7; ++k) {
            if (!std::getline(fields, field, ',')) throw InputError(path, where, "expected 7 comma-separated numbers");
            char* end = nullptr;
            v[k] = std::strtod(field.c_str(), &end);
            if (end == field.c_str() || *end != '\0') throw InputError(path, where, "\"" + field + "\" is not a number");
            if (!std::isfinite(v[k])) throw InputError(path, where, "NaN or infinite value");
            if (k == 0) index = field;
        }
        if (std::getline(fields, field, ',')) throw InputError(path, where, "more than 7 values");
        if (v[0] != row) throw InputError(path, where, "particle index " + index + " out of order (want " + std::to_string(row) + ")");
        state.x.col(row) = Vec3(v[1], v[2], v[3]);
        state.v.col(row) = Vec3(v[4], v[5], v[6]);
        ++row;
    }
    if (row != state.size())
        throw InputError(path, "(rows)", std::to_string(row) + " particles, the scene has " + std::to_string(state.size()));
}

}  // namespace clothlab
