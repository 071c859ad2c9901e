// `clothlab study precision`: error at a fixed end time against wall time, per method and Δt.
#include "clothlab/study/precision.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>

#include "clothlab/core/input_error.h"
#include "clothlab/exercise/03_pbd_loop.h"
#include "clothlab/sim/mass_spring.h"
#include "clothlab/sim/pbd.h"
#include "clothlab/sim/run.h"
#include "clothlab/study/plot.h"
#include "clothlab/study/stability.h"

namespace clothlab {
namespace {

Scene withMethod(Scene s, Method method, double dt) {
    s.solver.method = method;
    s.solver.dt = dt;
    return s;
}

long long stepsFor(double end_time, double dt) { return std::max<long long>(1, std::llround(end_time / dt)); }

/// RMS over the free particles (w > 0) of |x_i − ref_i|.
double rmsError(const State& s, const Matrix3X& ref) {
    double sum = 0.0;
    int n = 0;
    for (int i = 0; i < s.size(); ++i)
        if (s.w[i] > 0.0) sum += (s.x.col(i) - ref.col(i)).squaredNorm(), ++n;
    return n > 0 ? std::sqrt(sum / n) : 0.0;
}

std::vector<std::string> methodsOf(const PrecisionResult& r) {
    std::vector<std::string> m;
    for (const auto& run : r.runs)
        if (m.empty() || m.back() != run.series) m.push_back(run.series);
    return m;
}

/// True when the runs of `series` are position-based (budget sweeps, not Δt sweeps).
bool positionBasedSeries(const PrecisionResult& r, const std::string& series) {
    for (const auto& run : r.runs)
        if (run.series == series) return isPositionBased(run.method);
    return false;
}

/// Number of constraints a position-based simulation projects per iteration (distance + bending).
double constraintCount(const Simulation& sim) {
    const auto* pbd = dynamic_cast<const PbdSimulation*>(&sim);
    return pbd ? static_cast<double>(pbd->distanceLinks().size() + pbd->bendingStencilList().size()) : 0.0;
}

/// Steps `scene` to T with timing (best of up to `repeats` runs within 0.2 s); fills wall, unstable,
/// error, strain; returns the constraint count of the simulation.
double timedRun(const Scene& scene, long long steps, const Matrix3X& ref, int repeats, PrecisionRun& run) {
    double spent = 0.0, count = 0.0;
    for (int repeat = 0; repeat < std::max(1, repeats) && (repeat == 0 || spent < 0.2); ++repeat) {
        auto sim = makeSimulation(scene);
        const RunResult res = runSimulation(*sim, steps, steps);
        run.wall = repeat == 0 ? res.wall : std::min(run.wall, res.wall);
        spent += res.wall;
        run.unstable = res.unstable;
        run.error = res.unstable ? std::numeric_limits<double>::quiet_NaN() : rmsError(sim->state(), ref);
        run.strain = res.unstable ? std::numeric_limits<double>::quiet_NaN() : sim->strain().rms;
        count = constraintCount(*sim);
        if (res.unstable) break;
    }
    return count;
}

/// The position-based reference run with `substeps` substeps per frame, stepped to T.
std::unique_ptr<Simulation> positionBasedReference(const Scene& scene, const PrecisionOptions& o, int substeps) {
    const long long steps = stepsFor(o.end_time, scene.solver.dt);
    auto sim = makeSimulation(positionBasedScene(scene, o.reference_method, o.reference_iterations, substeps));
    const RunResult r = runSimulation(*sim, steps, steps);
    if (r.unstable) throw InputError(scene.file, "solver", std::string("the reference run (") + methodName(o.reference_method) + ") is unstable: " + r.message);
    return sim;
}

std::string positionBasedLabel(const Scene& scene, const PrecisionOptions& o) {
    std::ostringstream s;
    s << methodName(o.reference_method) << " with " << o.reference_substeps << " substeps x " << o.reference_iterations
      << " iteration(s) per frame (substep " << std::setprecision(4) << scene.solver.dt / o.reference_substeps << " s)";
    return s.str();
}

std::string fileName(std::string series) {
    for (auto& c : series)
        if (c == ' ') c = '_';
    return series;
}

}  // namespace

Scene positionBasedScene(const Scene& scene, Method method, int iterations, int substeps) {
    Scene s = scene;
    s.solver.method = method;
    s.solver.iterations = iterations;
    s.solver.substeps = substeps;
    // the stiffness per substep: n substeps remove what one step with k removed (exercise 3.2)
    const auto perSubstep = [substeps](double k) { return k >= 1.0 ? k : iterationStiffness(k, substeps); };
    s.pbd.damping = perSubstep(scene.pbd.damping);
    if (method == Method::Pbd) {
        s.constraints.distance.stiffness = perSubstep(scene.constraints.distance.stiffness);
        s.constraints.bending.stiffness = perSubstep(scene.constraints.bending.stiffness);
    }
    return s;
}

Matrix3X precisionReference(const Scene& scene, const PrecisionOptions& o, std::string* label) {
    if (const auto exact = singleSpringAnalytic(scene)) {
        auto sim = makeSimulation(withMethod(scene, Method::SymplecticEuler, scene.solver.dt));
        Matrix3X ref = sim->state().x;
        const Vec3 axis = (scene.spring.start - scene.spring.anchor).normalized();
        ref.col(1) = scene.spring.anchor + exact->position(o.end_time) * axis;
        if (label) *label = "analytic";
        return ref;
    }
    if (isPositionBased(o.reference_method)) {
        auto sim = positionBasedReference(scene, o, o.reference_substeps);
        if (label) *label = positionBasedLabel(scene, o);
        return sim->state().x;
    }
    const double dt = o.reference_dt > 0.0 ? o.reference_dt : o.dt_min / 8.0;
    const long long steps = stepsFor(o.end_time, dt);
    const double dt_exact = o.end_time / static_cast<double>(steps);
    auto sim = makeSimulation(withMethod(scene, o.reference_method, dt_exact));
    const RunResult r = runSimulation(*sim, steps, steps);
    if (r.unstable)
        throw InputError(scene.file, "solver", std::string("the reference run (") + methodName(o.reference_method) + ") is unstable: " + r.message);
    if (label) {
        std::ostringstream s;
        s << methodName(o.reference_method) << " at dt = " << std::setprecision(4) << dt_exact << " s";
        *label = s.str();
    }
    return sim->state().x;
}

PrecisionResult precisionStudy(const Scene& scene, const PrecisionOptions& o) {
    PrecisionResult r;
    r.scene = scene.file;
    r.end_time = o.end_time;
    Matrix3X ref;
    if (isPositionBased(o.reference_method)) {
        auto sim = positionBasedReference(scene, o, o.reference_substeps);
        ref = sim->state().x;
        r.reference = positionBasedLabel(scene, o);
        r.reference_strain = sim->strain().rms;
        // The reference's own error: how far it moves when its substeps are halved.
        auto coarse = positionBasedReference(scene, o, std::max(1, o.reference_substeps / 2));
        r.reference_change = rmsError(coarse->state(), ref);
    } else {
        ref = precisionReference(scene, o, &r.reference);
    }
    const std::vector<double> dts = logSpace(o.dt_min, o.dt_max, o.dt_count);
    int total = 0;
    for (Method m : o.methods)
        total += isPositionBased(m) ? static_cast<int>(o.sweeps.size() * o.budgets.size()) : static_cast<int>(dts.size());
    int done = 0;
    for (Method m : o.methods) {
        const std::string method = methodName(m);
        if (isPositionBased(m)) {
            r.position_based = true;
            for (const std::string& sweep : o.sweeps) {
                const std::string series = method + " " + sweep;
                for (int b : o.budgets) {
                    PrecisionRun run;
                    run.method = m;
                    run.series = series;
                    run.iterations = sweep == "iterations" ? b : 1;
                    run.substeps = sweep == "substeps" ? b : 1;
                    run.steps = stepsFor(o.end_time, scene.solver.dt);
                    run.dt = scene.solver.dt / run.substeps;
                    const Scene s = positionBasedScene(scene, m, run.iterations, run.substeps);
                    const double n = timedRun(s, run.steps, ref, o.repeats, run);
                    run.projections = n * run.iterations * run.substeps / scene.solver.dt;
                    r.runs.push_back(run);
                    if (o.progress) o.progress(++done, total, series + " " + std::to_string(b));
                }
                r.slopes[series] = costSlope(r.runs, series);
            }
            continue;
        }
        for (auto it = dts.rbegin(); it != dts.rend(); ++it) {  // largest dt first: quick runs first
            PrecisionRun run;
            run.method = m;
            run.series = method;
            run.steps = stepsFor(o.end_time, *it);
            run.dt = o.end_time / static_cast<double>(run.steps);
            timedRun(withMethod(scene, m, run.dt), run.steps, ref, o.repeats, run);
            r.runs.push_back(run);
            if (o.progress) o.progress(++done, total, method);
        }
        r.slopes[method] = convergenceSlope(r.runs, method);
    }
    return r;
}

double convergenceSlope(const std::vector<PrecisionRun>& runs, const std::string& method) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (const PrecisionRun& p : runs) {
        if (p.series != method || p.unstable || !(p.error > 1e-13) || !std::isfinite(p.error)) continue;
        const double x = std::log(p.dt), y = std::log(p.error);
        sx += x, sy += y, sxx += x * x, sxy += x * y, ++n;
    }
    if (n < 2) return std::numeric_limits<double>::quiet_NaN();
    const double den = n * sxx - sx * sx;
    return den != 0.0 ? (n * sxy - sx * sy) / den : std::numeric_limits<double>::quiet_NaN();
}

double costSlope(const std::vector<PrecisionRun>& runs, const std::string& series) {
    std::vector<PrecisionRun> as;  // the same fit with log(projections) in the place of log(dt)
    for (const PrecisionRun& p : runs)
        if (p.series == series && p.projections > 0.0) {
            PrecisionRun q = p;
            q.dt = p.projections;
            as.push_back(q);
        }
    return convergenceSlope(as, series);
}

void writePrecisionCsv(const std::string& path, const PrecisionResult& r) {
    std::ofstream out(path);
    if (!out) throw InputError(path, "(file)", "cannot write the file");
    out << std::setprecision(10) << "method,dt [s],steps,error [m],wall [s],unstable,series,iterations,substeps,projections_per_s [1/s],rms_strain [1]\n";
    for (const PrecisionRun& p : r.runs)
        out << methodName(p.method) << "," << p.dt << "," << p.steps << "," << p.error << "," << p.wall << "," << (p.unstable ? 1 : 0) << ","
            << p.series << "," << p.iterations << "," << p.substeps << "," << p.projections << "," << p.strain << "\n";
}

namespace {

void printPositionBasedTable(std::ostream& out, const PrecisionResult& r) {
    char buf[200];
    out << "position-based runs at the scene's frame step, error at T = " << r.end_time << " s (" << r.scene << ")\n"
        << "reference: " << r.reference << "; halving its substeps moves it by " << std::setprecision(3) << r.reference_change
        << " m RMS (its own error), its RMS edge strain is " << r.reference_strain << "\n"
        << "error = RMS over the free particles of |x - x_ref|; strain = RMS over the edges of (|x_i - x_j| - d)/d;\n"
        << "cost = constraint projections per simulated second = #constraints x iterations x substeps / frame dt\n";
    std::snprintf(buf, sizeof buf, "%-18s %5s %5s %14s %14s %12s %10s %12s\n", "series", "iter", "subst", "projections/s", "error [m]",
                  "rms strain", "wall [s]", "ms per frame");
    out << buf;
    for (const PrecisionRun& p : r.runs) {
        if (p.projections <= 0.0) continue;
        if (p.unstable)
            std::snprintf(buf, sizeof buf, "%-18s %5d %5d %14.4g %14s %12s %10.4g %12.4g\n", p.series.c_str(), p.iterations, p.substeps,
                          p.projections, "unstable", "-", p.wall, 1e3 * p.wall / static_cast<double>(p.steps));
        else
            std::snprintf(buf, sizeof buf, "%-18s %5d %5d %14.4g %14.4e %12.4e %10.4g %12.4g\n", p.series.c_str(), p.iterations, p.substeps,
                          p.projections, p.error, p.strain, p.wall, 1e3 * p.wall / static_cast<double>(p.steps));
        out << buf;
    }
    out << "work-precision slope (log error over log projections; -1: ten times the cost, ten times less error; 0: no gain):\n";
    for (const std::string& m : methodsOf(r)) {
        if (!r.slopes.count(m) || !positionBasedSeries(r, m)) continue;
        std::snprintf(buf, sizeof buf, "  %-18s %6.2f\n", m.c_str(), r.slopes.at(m));
        out << buf;
    }
    // Equal cost: at every budget, which series has the smallest position error (ties: all of them,
    // e.g. PBD with k = 1 and XPBD with α = 0 compute the same thing).
    std::map<double, std::vector<const PrecisionRun*>> atCost;
    for (const PrecisionRun& p : r.runs)
        if (p.projections > 0.0 && !p.unstable) atCost[p.projections].push_back(&p);
    out << "smallest error at equal cost:\n";
    for (const auto& [cost, runs] : atCost) {
        double best = runs.front()->error;
        for (const PrecisionRun* p : runs) best = std::min(best, p->error);
        std::string names;
        int iterations = 0, substeps = 0;
        for (const PrecisionRun* p : runs)
            if (p->error <= best * (1.0 + 1e-9)) {
                names += (names.empty() ? "" : " = ") + p->series;
                iterations = p->iterations, substeps = p->substeps;
            }
        std::snprintf(buf, sizeof buf, "  %12.4g projections/s: %.3e m  %s (%d iteration(s) x %d substep(s))\n", cost, best, names.c_str(),
                      iterations, substeps);
        out << buf;
    }
}

}  // namespace

void printPrecisionTable(std::ostream& out, const PrecisionResult& r) {
    if (r.position_based) {
        printPositionBasedTable(out, r);
        bool forceBased = false;
        for (const PrecisionRun& p : r.runs) forceBased = forceBased || p.projections <= 0.0;
        if (!forceBased) return;
    }
    char buf[160];
    out << "error at T = " << r.end_time << " s against the " << r.reference << " solution (" << r.scene
        << "); error = RMS over the free particles of |x - x_ref|\n";
    std::snprintf(buf, sizeof buf, "%-18s %12s %10s %14s %12s %14s\n", "method", "dt [s]", "steps", "error [m]", "wall [s]", "us per step");
    out << buf;
    for (const PrecisionRun& p : r.runs) {
        if (p.projections > 0.0) continue;
        if (p.unstable)
            std::snprintf(buf, sizeof buf, "%-18s %12.4g %10lld %14s %12.4g %14.3g\n", methodName(p.method), p.dt, p.steps, "unstable", p.wall,
                          1e6 * p.wall / static_cast<double>(p.steps));
        else
            std::snprintf(buf, sizeof buf, "%-18s %12.4g %10lld %14.4e %12.4g %14.3g\n", methodName(p.method), p.dt, p.steps, p.error, p.wall,
                          1e6 * p.wall / static_cast<double>(p.steps));
        out << buf;
    }
    out << "measured order (slope of log error over log dt; theory: explicit/symplectic/implicit Euler 1, Verlet 2, RK4 4):\n";
    for (const std::string& m : methodsOf(r)) {
        if (positionBasedSeries(r, m)) continue;
        std::snprintf(buf, sizeof buf, "  %-18s %6.2f\n", m.c_str(), r.slopes.count(m) ? r.slopes.at(m) : NAN);
        out << buf;
    }
}

namespace {

/// The two-panel work-precision plot of the position-based series (and precision_wall.png).
std::vector<std::string> plotPositionBased(const std::string& dir, const PrecisionResult& r, const std::vector<std::string>& series) {
    std::vector<std::string> written;
    auto lines = [&](const std::string& xcol, const std::string& ycol) {
        std::ostringstream s;
        for (size_t i = 0; i < series.size(); ++i) {
            std::string t = series[i];
            s << (i ? ", \\\n     " : "") << "'precision_" << fileName(series[i]) << ".dat' using " << xcol << ":" << ycol
              << " with linespoints lw 2 pt " << 5 + static_cast<int>(i) << " dt " << (t.find("xpbd") == 0 ? 2 : 1) << " title '" << t << "'";
        }
        return s.str() + "\n";
    };
    // Right panel: the strain, with the reference's strain as a horizontal line.
    std::string strainPlot = "plot " + lines("4", "5");
    if (std::isfinite(r.reference_strain) && r.reference_strain > 0.0) {
        std::ostringstream ref;
        ref << std::setprecision(6) << r.reference_strain;
        strainPlot.pop_back();
        strainPlot += ", \\\n     " + ref.str() + " with lines dt 3 lw 1.5 lc 'black' title 'reference'\n";
    }
    std::ostringstream s;
    s << "cd '" << dir << "'\nset terminal pngcairo size 1000,430 font ',10'\nset output 'precision.png'\n"
      << "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\nset grid\nset key bottom left font ',9' noenhanced\n"
      << "set multiplot layout 1,2 title \"work-precision at T = " << r.end_time << " s: " << r.scene << "\\nreference: " << r.reference
      << "\" noenhanced\n"  // double quotes: gnuplot reads \n as a line break
      << "set xlabel 'constraint projections per simulated second'\nset ylabel 'position error RMS |x - x_{ref}| [m]'\n"
      << "plot " << lines("4", "2") << "set ylabel 'RMS edge strain'\n" << strainPlot;
    s << "unset multiplot\n";
    if (runGnuplot(dir + "/precision.gp", s.str())) written.push_back(dir + "/precision.png");
    std::ostringstream w;
    w << "cd '" << dir << "'\nset terminal pngcairo size 720,520 font ',10'\nset output 'precision_wall.png'\n"
      << "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\nset grid\nset key bottom left font ',9' noenhanced\n"
      << "set title 'work-precision: " << r.scene << "' noenhanced\n"
      << "set xlabel 'wall time [s]'\nset ylabel 'position error at T = " << r.end_time << " s [m]'\n"
      << "plot " << lines("3", "2");
    if (runGnuplot(dir + "/precision_wall.gp", w.str())) written.push_back(dir + "/precision_wall.png");
    return written;
}

}  // namespace

std::vector<std::string> plotPrecision(const std::string& dir, const PrecisionResult& r) {
    const std::vector<std::string> methods = methodsOf(r);
    for (const std::string& m : methods) {
        std::ofstream d(dir + "/precision_" + fileName(m) + ".dat");
        d << std::setprecision(10) << "# dt error wall projections_per_s rms_strain\n";
        for (const PrecisionRun& p : r.runs)
            if (p.series == m && !p.unstable && p.error > 0.0) d << p.dt << " " << p.error << " " << p.wall << " " << p.projections << " " << p.strain << "\n";
    }
    if (r.position_based) return plotPositionBased(dir, r, methods);
    std::vector<std::string> written;
    auto script = [&](const std::string& png, const std::string& xlabel, const std::string& column, bool with_slope) {
        std::ostringstream s;
        s << "cd '" << dir << "'\nset terminal pngcairo size 720,520 font ',10'\nset output '" << png << "'\n"
          << "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\nset grid\n"
          << "set xlabel '" << xlabel << "'\nset ylabel 'error at T = " << r.end_time << " s [m]'\n"
          << "set key outside right font ',9'\n"
          << "set title '" << (with_slope ? "convergence" : "work-precision") << ": " << r.scene << " (reference: " << r.reference << ")' noenhanced\n"
          << "plot ";
        for (size_t i = 0; i < methods.size(); ++i) {
            const double slope = r.slopes.count(methods[i]) ? r.slopes.at(methods[i]) : NAN;
            char title[96];
            if (with_slope) std::snprintf(title, sizeof title, "%s (slope %.2f)", methods[i].c_str(), slope);
            else std::snprintf(title, sizeof title, "%s", methods[i].c_str());
            std::string t = title;
            for (auto& ch : t) if (ch == '_') ch = ' ';
            s << (i ? ", \\\n     " : "") << "'precision_" << methods[i] << ".dat' using " << column << ":2 with linespoints lw 2 pt "
              << 5 + static_cast<int>(i) << " title '" << t << "'";
        }
        s << "\n";
        return s.str();
    };
    if (runGnuplot(dir + "/precision.gp", script("precision.png", "wall time [s]", "3", false))) written.push_back(dir + "/precision.png");
    if (runGnuplot(dir + "/convergence.gp", script("convergence.png", "time step {/Symbol D}t [s]", "1", true)))
        written.push_back(dir + "/convergence.png");
    return written;
}

}  // namespace clothlab
