// `clothlab study extremes`: every extreme case, every method that applies, classified.
#include "clothlab/study/extremes.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

#include "clothlab/core/input_error.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/sim/colliders.h"
#include "clothlab/sim/mass_spring.h"
#include "clothlab/study/plot.h"

namespace clothlab {
namespace {

std::string num(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

using Make = std::function<std::unique_ptr<Simulation>(Method, double, double)>;

// A force-based case: a shipped scene with the method, Δt and stiffness set, then changed by `edit`.
// kFields: each stiffness field with its share of k (a cloth: structural k, shear k/2, bending k/10).
Make forceCase(const std::string& file, std::vector<std::string> sets, const std::vector<std::pair<std::string, double>>& kFields,
               std::function<std::unique_ptr<Simulation>(Scene&)> edit = {}) {
    return [=](Method m, double k, double dt) {
        std::vector<std::string> s = sets;
        s.push_back(std::string("solver.method=") + methodName(m));
        s.push_back("solver.dt=" + num(dt));
        for (const auto& [field, share] : kFields) s.push_back(field + "=" + num(share * k));
        Scene scene = loadScene(file, s);
        return edit ? edit(scene) : makeSimulation(scene);
    };
}

// A chain whose free particles 1, 2, ... alternate between masses 1/sqrt(ratio) and sqrt(ratio) kg (w = 1/m).
std::unique_ptr<Simulation> chainWithMassRatio(Scene& s, double ratio) {
    MassSpringModel model = makeChain(s.chain);
    for (int i = 1; i < model.state.size(); ++i) model.state.w[i] = i % 2 ? std::sqrt(ratio) : 1.0 / std::sqrt(ratio);
    return std::make_unique<MassSpringSimulation>(s, model);
}

// A position-based case: a 5 x 5 cloth with distance and bending constraints 0.3 m above the ground
// plane, iterations (pbd) or compliance (xpbd) p, edited before (`scene`) and after (`state`) it is built.
Make clothCase(const std::string& file, std::function<void(Scene&)> scene, std::function<void(State&)> state) {
    return [=](Method m, double p, double dt) {
        std::vector<std::string> s = {"cloth.nx=5", "cloth.ny=5", "cloth.tilt=0", "cloth.origin=[-0.5,0.3,-0.5]",
                                      "constraints.bending.stiffness=0.1", std::string("solver.method=") + methodName(m),
                                      "solver.dt=" + num(dt)};
        if (m == Method::Pbd) s.push_back("solver.iterations=" + num(p));
        else s.insert(s.end(), {"constraints.distance.compliance=" + num(p), "constraints.bending.compliance=" + num(p)});
        Scene sc = loadScene(file, s);
        if (scene) scene(sc);
        std::unique_ptr<Simulation> sim = makeSimulation(sc);
        if (state) state(sim->state());
        return sim;
    };
}

}  // namespace

std::vector<ExtremeCase> extremeCases(const std::string& dir) {
    const std::string spring = dir + "/spring.json", chain = dir + "/chain.json", cloth = dir + "/mfn_hanging.json",
                      ground = dir + "/pbd_ground.json";
    const std::vector<std::pair<std::string, double>> clothK = {{"springs.structural.k", 1.0}, {"springs.shear.k", 0.5}, {"springs.bending.k", 0.1}};
    std::vector<ExtremeCase> c;
    c.push_back({"single spring", false, forceCase(spring, {}, {{"spring.k", 1.0}})});
    for (double ratio : {1.0, 1e3, 1e6})
        c.push_back({"chain, mass ratio " + num(ratio), false,
                     forceCase(chain, {"chain.particles=6"}, {{"chain.k", 1.0}}, [ratio](Scene& s) { return chainWithMassRatio(s, ratio); })});
    c.push_back({"chain of zero-length springs, every particle coincident", false,
                 forceCase(chain, {"chain.l0=0", "chain.particles=5"}, {{"chain.k", 1.0}})});
    c.push_back({"chain with two coincident particles (l0 > 0)", false,
                 forceCase(chain, {"chain.particles=5"}, {{"chain.k", 1.0}}, [](Scene& s) -> std::unique_ptr<Simulation> {
                     MassSpringModel model = makeChain(s.chain);
                     model.state.x.col(3) = model.state.x.col(2);
                     return std::make_unique<MassSpringSimulation>(s, model);
                 })});
    c.push_back({"4 x 4 cloth", false, forceCase(cloth, {"cloth.nx=4", "cloth.ny=4"}, clothK)});
    c.push_back({"4 x 4 cloth of zero width (zero-length springs)", false,
                 forceCase(cloth, {"cloth.nx=4", "cloth.ny=4"}, clothK, [](Scene& s) {
                     s.cloth.width = 0.0;
                     return makeSimulation(s);
                 })});

    c.push_back({"cloth onto the ground (flat dihedrals)", true, clothCase(ground, {}, {})});
    c.push_back({"cloth, mass ratio 1e6", true, clothCase(ground, {}, [](State& s) {
                     for (int i = 0; i < s.size(); ++i) s.w[i] = i % 2 ? 1e3 : 1e-3;
                 })});
    c.push_back({"cloth of zero width (zero-area triangles)", true, clothCase(ground, [](Scene& s) { s.cloth.width = 0.0; }, {})});
    c.push_back({"cloth collapsed to a point (every particle coincident)", true,
                 clothCase(ground, [](Scene& s) { s.cloth.width = s.cloth.height = 0.0; }, {})});
    c.push_back({"cloth with two coincident particles", true, clothCase(ground, {}, [](State& s) { s.x.col(7) = s.x.col(8); })});
    c.push_back({"cloth folded in half onto itself (dihedral pi)", true, clothCase(ground, {}, [](State& s) {
                     const double fold = s.x(0, 2);  // the middle column of the 5 x 5 grid
                     for (int i = 0; i < s.size(); ++i)
                         if (i % 5 > 2) s.x(0, i) = 2 * fold - s.x(0, i);
                 })});
    c.push_back({"cloth with all-pinned stencils (two rows pinned)", true, clothCase(ground, [](Scene& s) {
                     s.cloth.pins.clear();
                     for (int i = 0; i < 10; ++i) s.cloth.pins.push_back(i);
                 }, {})});
    return c;
}

std::string extremeAxis(Method m) {
    if (m == Method::Pbd) return "iterations [1]";
    if (m == Method::Xpbd) return "compliance [m/N]";
    return "k [N/m]";
}

ExtremeCell classifyExtremeRun(Simulation& sim, long long steps) {
    ExtremeCell cell;
    const Scene& sc = sim.scene();
    cell.method = sc.solver.method;
    cell.dt = sc.solver.dt;
    const double h = sc.solver.thickness, deep = std::max(4 * h, 1e-3);
    std::vector<std::vector<char>> outside;  // per collider: free particles that start outside (d ≥ −h)
    for (const Collider& c : sc.colliders) {
        outside.emplace_back();
        for (int i = 0; i < sim.state().size(); ++i)
            outside.back().push_back(sim.state().w[i] > 0 && colliderDistance(c, sim.state().x.col(i)) >= -h);
    }
    const double e0 = sim.energy(), eScale = energyScale(sim);
    std::string nonFinite, through;
    double growth = 0.0;
    const RunResult r = runSimulation(sim, steps, 1, [&](const ReportRow& row) {
        for (const Metric& m : row.metrics)
            if (!std::isfinite(m.value) && nonFinite.empty()) nonFinite = m.name + " is " + num(m.value) + " at step " + std::to_string(row.step);
        growth = std::max(growth, (sim.energy() - e0) / eScale);
        for (size_t k = 0; k < outside.size() && through.empty(); ++k)
            for (int i = 0; i < sim.state().size(); ++i)
                if (outside[k][static_cast<size_t>(i)] && colliderDistance(sc.colliders[k], sim.state().x.col(i)) < -deep) {
                    through = "particle " + std::to_string(i) + " is through collider " + std::to_string(k) + " at step " + std::to_string(row.step);
                    break;
                }
    });
    bool flagged = false;
    for (const RunWarning& w : r.warnings) flagged = flagged || w.kind == WarningKind::FellThrough;
    std::string wrong = nonFinite.empty() ? "" : "NaN/Inf in the report: " + nonFinite;
    if (wrong.empty() && !r.unstable && !sim.state().isFinite()) wrong = "NaN/Inf in the state";
    if (wrong.empty() && !r.unstable && !through.empty() && !flagged) wrong = through + " without a fell-through warning";
    if (wrong.empty() && !r.unstable && r.warnings.empty() && growth > 100.0)
        wrong = "energy rose by " + num(growth) + " E_scale without a stop or warning";
    if (!wrong.empty()) {
        cell.outcome = ExtremeOutcome::SilentlyWrong;
        cell.message = wrong;
    } else if (r.unstable) {
        cell.outcome = ExtremeOutcome::Stopped;
        cell.step = r.steps;
        cell.message = r.message;
    } else if (!r.warnings.empty()) {
        cell.outcome = ExtremeOutcome::Warned;
        cell.step = r.warnings.front().step;
        for (const RunWarning& w : r.warnings) cell.step = std::min(cell.step, w.step);
        cell.message = warningHeadline(r.warnings.front(), sc);
    }
    return cell;
}

std::vector<ExtremeCell> extremesStudy(const std::vector<ExtremeCase>& cases, const ExtremesOptions& o) {
    auto axis = [&](Method m) { return m == Method::Pbd ? o.iterations : m == Method::Xpbd ? o.compliances : o.ks; };
    auto applies = [](const ExtremeCase& c, Method m) { return c.position_based == isPositionBased(m); };
    int total = 0, done = 0;
    for (const ExtremeCase& c : cases)
        for (Method m : o.methods)
            if (applies(c, m)) total += static_cast<int>(axis(m).size() * o.dts.size());
    std::vector<ExtremeCell> cells;
    for (const ExtremeCase& c : cases)
        for (Method m : o.methods) {
            if (!applies(c, m)) continue;
            for (double dt : o.dts)
                for (double p : axis(m)) {
                    ExtremeCell cell;
                    try {
                        auto sim = c.make(m, p, dt);
                        cell = classifyExtremeRun(*sim, o.steps);
                    } catch (const InputError& e) {  // a case the method refuses: said, not run
                        cell.outcome = ExtremeOutcome::Stopped;
                        cell.message = std::string("refused: ") + e.what();
                    }
                    cell.case_name = c.name, cell.method = m, cell.p = p, cell.dt = dt;
                    cells.push_back(cell);
                    if (o.progress) o.progress(++done, total, c.name);
                }
        }
    return cells;
}

namespace {
const char* outcomeName(ExtremeOutcome o) {
    switch (o) {
        case ExtremeOutcome::Stable: return "stable";
        case ExtremeOutcome::Stopped: return "stopped";
        case ExtremeOutcome::Warned: return "warned";
        case ExtremeOutcome::SilentlyWrong: return "silently_wrong";
    }
    return "";
}
char outcomeChar(ExtremeOutcome o) { return ".uwX"[static_cast<int>(o)]; }  // in the order of the enum

// Rows of the table: (case, method) in the order run, with their cells.
std::vector<std::pair<std::string, std::vector<const ExtremeCell*>>> rowsOf(const std::vector<ExtremeCell>& cells) {
    std::vector<std::pair<std::string, std::vector<const ExtremeCell*>>> rows;
    for (const ExtremeCell& c : cells) {
        const std::string key = c.case_name + " | " + methodName(c.method);
        if (rows.empty() || rows.back().first != key) rows.push_back({key, {}});
        rows.back().second.push_back(&c);
    }
    return rows;
}
std::string quoted(std::string s) {
    for (char& ch : s) if (ch == '"') ch = '\'';
    return "\"" + s + "\"";
}
}  // namespace

void writeExtremesCsv(const std::string& path, const std::vector<ExtremeCell>& cells) {
    std::ofstream out(path);
    if (!out) throw InputError(path, "(file)", "cannot write the file");
    out << std::setprecision(10) << "case,method,axis,p,dt [s],outcome,step,message\n";
    for (const ExtremeCell& c : cells)
        out << quoted(c.case_name) << "," << methodName(c.method) << "," << quoted(extremeAxis(c.method)) << "," << c.p << "," << c.dt << ","
            << outcomeName(c.outcome) << "," << c.step << "," << quoted(c.message) << "\n";
}

void writeExtremesMarkdown(std::ostream& out, const std::vector<ExtremeCell>& cells, const std::string& command) {
    int counts[4] = {0, 0, 0, 0};
    for (const ExtremeCell& c : cells) ++counts[static_cast<int>(c.outcome)];
    out << "`" << command << "`: " << cells.size() << " runs, " << counts[0] << " stable, " << counts[2] << " warned, " << counts[1]
        << " stopped unstable, **" << counts[3] << " silently wrong**.\n\n"
        << "Map: one group per time step (Δt from the smallest to the largest), one character per value of the "
           "method's axis (smallest first): `.` stable, `w` ran to the end with a warning, `u` stopped as unstable, "
           "`X` silently wrong. Steps: the first step reported (stop or warning), smallest and largest over the row.\n\n"
        << "| case | method | axis | map | stable | warned | stopped | silently wrong | reported at steps |\n"
        << "|---|---|---|---|---|---|---|---|---|\n";
    std::map<std::string, std::string> axes;  // axis -> its values, for the legend below the table
    for (const auto& [key, row] : rowsOf(cells)) {
        int n[4] = {0, 0, 0, 0};
        long long lo = -1, hi = -1;
        std::string map;
        double dt = row.front()->dt;
        for (const ExtremeCell* c : row) {
            if (c->dt != dt) map += ' ', dt = c->dt;
            map += outcomeChar(c->outcome);
            ++n[static_cast<int>(c->outcome)];
            if (c->step > 0) lo = lo < 0 ? c->step : std::min(lo, c->step), hi = std::max(hi, c->step);
        }
        std::string& values = axes[extremeAxis(row.front()->method)];
        if (values.empty())
            for (const ExtremeCell* c : row)
                if (c->dt == row.front()->dt) values += (values.empty() ? "" : ", ") + num(c->p);
        out << "| " << row.front()->case_name << " | " << methodName(row.front()->method) << " | " << extremeAxis(row.front()->method)
            << " | `" << map << "` | " << n[0] << " | " << n[2] << " | " << n[1] << " | " << n[3] << " | "
            << (lo < 0 ? "-" : std::to_string(lo) + (hi != lo ? "–" + std::to_string(hi) : "")) << " |\n";
    }
    std::string dts;
    for (const ExtremeCell& c : cells)
        if (c.case_name == cells.front().case_name && c.method == cells.front().method && dts.find(" " + num(c.dt) + ",") == std::string::npos)
            dts += " " + num(c.dt) + ",";
    if (!dts.empty()) out << "\nTime steps Δt [s]:" << dts.substr(0, dts.size() - 1) << ".";
    for (const auto& [axis, values] : axes) out << " Axis " << axis << ": " << values << ".";
    out << "\n";
    out << "\nSilently wrong cells:";
    if (counts[3] == 0) out << " none.\n";
    else {
        out << "\n";
        for (const ExtremeCell& c : cells)
            if (c.outcome == ExtremeOutcome::SilentlyWrong)
                out << "- " << c.case_name << ", " << methodName(c.method) << ", " << extremeAxis(c.method) << " " << num(c.p) << ", dt = " << num(c.dt)
                    << " s: " << c.message << "\n";
    }
}

std::string plotExtremes(const std::string& dir, const std::vector<ExtremeCell>& cells) {
    const auto rows = rowsOf(cells);
    std::vector<double> dts;  // every time step, ascending: one group of squares each
    for (const ExtremeCell& c : cells)
        if (std::find(dts.begin(), dts.end(), c.dt) == dts.end()) dts.push_back(c.dt);
    std::sort(dts.begin(), dts.end());
    size_t width = 1;  // squares per group: the longest axis
    for (const auto& row : rows) width = std::max(width, row.second.size() / std::max<size_t>(1, dts.size()));
    auto group = [&](double dt) { return static_cast<size_t>(std::find(dts.begin(), dts.end(), dt) - dts.begin()); };
    {
        std::ofstream d(dir + "/extremes.dat");
        d << "# x row outcome(0 stable, 1 stopped, 2 warned, 3 silently wrong)\n";
        for (size_t y = 0; y < rows.size(); ++y) {
            std::map<double, size_t> seen;
            for (const ExtremeCell* c : rows[y].second)
                d << group(c->dt) * (width + 1) + seen[c->dt]++ << " " << y << " " << static_cast<int>(c->outcome) << "\n";
        }
    }
    const size_t groups = dts.size();
    std::ostringstream s;
    s << "cd '" << dir << "'\nset terminal pngcairo size 1400," << 120 + 16 * rows.size() << " font ',8'\nset output 'extremes.png'\n"
      << "set title 'clothlab study extremes: per case and method, one square per run (groups: time steps, small to large; "
         "inside a group: the method axis, small to large)' noenhanced\n"
      << "set yrange [" << rows.size() << "-0.5:-0.5]\nset xrange [-1:" << groups * (width + 1) << "]\nset ytics (";
    for (size_t y = 0; y < rows.size(); ++y) s << (y ? ", " : "") << quoted(rows[y].first) << " " << y;
    s << ") noenhanced font ',7'\nset xtics (";
    for (size_t g = 0; g < groups; ++g) s << (g ? ", " : "") << "'dt = " << num(dts[g]) << " s' " << g * (width + 1) + (width - 1) / 2.0;
    s << ") noenhanced\nset key below horizontal\nset grid noxtics noytics\n"
      << "plot 'extremes.dat' using 1:($3 == 0 ? $2 : 1/0) with points pt 5 ps 1.1 lc rgb '#2a9d3a' title 'stable', \\\n"
      << "     '' using 1:($3 == 2 ? $2 : 1/0) with points pt 5 ps 1.1 lc rgb '#e69f00' title 'warned (ran, with a warning)', \\\n"
      << "     '' using 1:($3 == 1 ? $2 : 1/0) with points pt 5 ps 1.1 lc rgb '#1f5fbf' title 'stopped as unstable', \\\n"
      << "     '' using 1:($3 == 3 ? $2 : 1/0) with points pt 7 ps 1.6 lc rgb '#d62728' title 'silently wrong'\n";
    return runGnuplot(dir + "/extremes.gp", s.str()) ? dir + "/extremes.png" : "";
}

}  // namespace clothlab
