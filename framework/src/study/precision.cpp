// `clothlab study precision`: error at a fixed end time against wall time, per method and Δt.
#include "clothlab/study/precision.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

#include "clothlab/core/input_error.h"
#include "clothlab/sim/mass_spring.h"
#include "clothlab/sim/run.h"
#include "clothlab/study/plot.h"
#include "clothlab/study/stability.h"

namespace clothlab {
namespace {

Scene withMethod(Scene s, const std::string& method, double dt) {
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
        if (m.empty() || m.back() != run.method) m.push_back(run.method);
    return m;
}

}  // namespace

Matrix3X precisionReference(const Scene& scene, const PrecisionOptions& o, std::string* label) {
    if (const auto exact = singleSpringAnalytic(scene)) {
        auto sim = makeSimulation(withMethod(scene, "symplectic_euler", scene.solver.dt));
        Matrix3X ref = sim->state().x;
        const Vec3 axis = (scene.spring.start - scene.spring.anchor).normalized();
        ref.col(1) = scene.spring.anchor + exact->position(o.end_time) * axis;
        if (label) *label = "analytic";
        return ref;
    }
    const double dt = o.reference_dt > 0.0 ? o.reference_dt : o.dt_min / 8.0;
    const long long steps = stepsFor(o.end_time, dt);
    const double dt_exact = o.end_time / static_cast<double>(steps);
    auto sim = makeSimulation(withMethod(scene, o.reference_method, dt_exact));
    const RunResult r = runSimulation(*sim, steps, steps);
    if (r.unstable)
        throw InputError(scene.file, "solver", "the reference run (" + o.reference_method + ") is unstable: " + r.message);
    if (label) {
        std::ostringstream s;
        s << o.reference_method << " at dt = " << std::setprecision(4) << dt_exact << " s";
        *label = s.str();
    }
    return sim->state().x;
}

PrecisionResult precisionStudy(const Scene& scene, const PrecisionOptions& o) {
    PrecisionResult r;
    r.scene = scene.file;
    r.end_time = o.end_time;
    const Matrix3X ref = precisionReference(scene, o, &r.reference);
    const std::vector<double> dts = logSpace(o.dt_min, o.dt_max, o.dt_count);
    const int total = static_cast<int>(o.methods.size() * dts.size());
    int done = 0;
    for (const std::string& method : o.methods) {
        for (auto it = dts.rbegin(); it != dts.rend(); ++it) {  // largest dt first: quick runs first
            PrecisionRun run;
            run.method = method;
            run.steps = stepsFor(o.end_time, *it);
            run.dt = o.end_time / static_cast<double>(run.steps);
            // Short runs are timed several times (best of up to 5 within 0.2 s): timer noise.
            double spent = 0.0;
            for (int repeat = 0; repeat < 5 && (repeat == 0 || spent < 0.2); ++repeat) {
                auto sim = makeSimulation(withMethod(scene, method, run.dt));
                const RunResult res = runSimulation(*sim, run.steps, run.steps);
                run.wall = repeat == 0 ? res.wall : std::min(run.wall, res.wall);
                spent += res.wall;
                run.unstable = res.unstable;
                run.error = res.unstable ? std::numeric_limits<double>::quiet_NaN() : rmsError(sim->state(), ref);
                if (res.unstable) break;
            }
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
        if (p.method != method || p.unstable || !(p.error > 1e-13) || !std::isfinite(p.error)) continue;
        const double x = std::log(p.dt), y = std::log(p.error);
        sx += x, sy += y, sxx += x * x, sxy += x * y, ++n;
    }
    if (n < 2) return std::numeric_limits<double>::quiet_NaN();
    const double den = n * sxx - sx * sx;
    return den != 0.0 ? (n * sxy - sx * sy) / den : std::numeric_limits<double>::quiet_NaN();
}

void writePrecisionCsv(const std::string& path, const PrecisionResult& r) {
    std::ofstream out(path);
    if (!out) throw InputError(path, "(file)", "cannot write the file");
    out << std::setprecision(10) << "method,dt,steps,error,wall,unstable\n";
    for (const PrecisionRun& p : r.runs)
        out << p.method << "," << p.dt << "," << p.steps << "," << p.error << "," << p.wall << "," << (p.unstable ? 1 : 0) << "\n";
}

void printPrecisionTable(std::ostream& out, const PrecisionResult& r) {
    char buf[160];
    out << "error at T = " << r.end_time << " s against the " << r.reference << " solution (" << r.scene
        << "); error = RMS over the free particles of |x - x_ref|\n";
    std::snprintf(buf, sizeof buf, "%-18s %12s %10s %14s %12s %14s\n", "method", "dt [s]", "steps", "error [m]", "wall [s]", "us per step");
    out << buf;
    for (const PrecisionRun& p : r.runs) {
        if (p.unstable)
            std::snprintf(buf, sizeof buf, "%-18s %12.4g %10lld %14s %12.4g %14.3g\n", p.method.c_str(), p.dt, p.steps, "unstable", p.wall,
                          1e6 * p.wall / static_cast<double>(p.steps));
        else
            std::snprintf(buf, sizeof buf, "%-18s %12.4g %10lld %14.4e %12.4g %14.3g\n", p.method.c_str(), p.dt, p.steps, p.error, p.wall,
                          1e6 * p.wall / static_cast<double>(p.steps));
        out << buf;
    }
    out << "measured order (slope of log error over log dt; theory: explicit/symplectic/implicit Euler 1, Verlet 2, RK4 4):\n";
    for (const std::string& m : methodsOf(r)) {
        std::snprintf(buf, sizeof buf, "  %-18s %6.2f\n", m.c_str(), r.slopes.count(m) ? r.slopes.at(m) : NAN);
        out << buf;
    }
}

std::vector<std::string> plotPrecision(const std::string& dir, const PrecisionResult& r) {
    const std::vector<std::string> methods = methodsOf(r);
    for (const std::string& m : methods) {
        std::ofstream d(dir + "/precision_" + m + ".dat");
        d << std::setprecision(10) << "# dt error wall\n";
        for (const PrecisionRun& p : r.runs)
            if (p.method == m && !p.unstable && p.error > 0.0) d << p.dt << " " << p.error << " " << p.wall << "\n";
    }
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
