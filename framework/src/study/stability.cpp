// `clothlab study stability`: which (k, Δt) each integrator survives, against theory.
#include "clothlab/study/stability.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>

#include "clothlab/core/input_error.h"
#include "clothlab/sim/run.h"
#include "clothlab/sim/simulation.h"
#include "clothlab/study/plot.h"
#include "clothlab/study/theory.h"

namespace clothlab {
namespace {

Scene withMethod(Scene s, Method method, double dt) {
    s.solver.method = method;
    s.solver.dt = dt;
    return s;
}

std::string fmt(double x, int precision = 3) {
    std::ostringstream s;
    s << std::setprecision(precision) << x;
    return s.str();
}

}  // namespace

StabilityVerdict classifyStability(const Scene& scene, const StabilityCriteria& criteria) {
    StabilityVerdict v;
    auto sim = makeSimulation(scene);
    // Scales: extent L of the initial positions, initial energy, E_scale (run.h: energyScale()).
    const State& s0 = sim->state();
    const double extent = s0.size() > 0 ? (s0.x.rowwise().maxCoeff() - s0.x.rowwise().minCoeff()).norm() : 0.0;
    const double bound = 1e3 * (extent + 1.0);  // a blow-up long before the numbers overflow
    const double e0 = sim->energy();
    const double e_scale = energyScale(*sim);
    const long long check_every = std::max<long long>(1, criteria.steps / 100);
    auto unstable = [&](const std::string& why) {
        v.stable = false;
        v.reason = why;
        return v;
    };
    for (v.steps = 1; v.steps <= criteria.steps; ++v.steps) {
        if (const std::string why = stepAndCheck(*sim, v.steps, bound); !why.empty()) return unstable(why);
        if (v.steps % check_every == 0 || v.steps == criteria.steps) {
            const double growth = (sim->energy() - e0) / e_scale;
            v.energy_growth = std::max(v.energy_growth, growth);
            if (!std::isfinite(growth)) return unstable("energy NaN or Inf");
            if (growth > criteria.energy_factor) return unstable("energy grew by " + fmt(growth) + " E_scale");
        }
    }
    v.steps = criteria.steps;
    return v;
}

std::vector<double> logSpace(double lo, double hi, int count) {
    std::vector<double> v;
    for (int i = 0; i < count; ++i)
        v.push_back(count == 1 ? lo : lo * std::pow(hi / lo, static_cast<double>(i) / (count - 1)));
    return v;
}

StabilityResult stabilitySweep(const Scene& scene, const StabilityOptions& o) {
    StabilityResult r;
    r.scene = scene.file;
    r.model = scene.model;
    r.k_ref = sceneStiffness(scene);
    r.omega_ref = maxAngularFrequency(scene);
    {
        const State s = makeSimulation(withMethod(scene, Method::SymplecticEuler, scene.solver.dt))->state();
        r.min_mass = std::numeric_limits<double>::infinity();
        for (int i = 0; i < s.size(); ++i) if (s.w[i] > 0.0) r.min_mass = std::min(r.min_mass, 1.0 / s.w[i]);
    }
    const std::vector<double> ks = logSpace(o.k_min, o.k_max, o.k_count), dts = logSpace(o.dt_min, o.dt_max, o.dt_count);
    const int total = static_cast<int>(o.methods.size() * ks.size() * dts.size());
    int done = 0;
    for (Method method : o.methods)
        for (double k : ks) {
            const Scene sk = withStiffness(scene, k);
            const double omega = r.k_ref > 0.0 ? r.omega_ref * std::sqrt(k / r.k_ref) : 0.0;
            for (double dt : dts) {
                StabilityPoint p{method, k, dt, omega, {}};
                p.verdict = classifyStability(withMethod(sk, method, dt), o.criteria);
                r.points.push_back(p);
                if (o.progress) o.progress(++done, total, methodName(method));
            }
        }
    return r;
}

double measureCriticalDt(const Scene& scene, Method method, double dt_lo, double dt_hi,
                         const StabilityCriteria& criteria, double rel_tol) {
    auto stable = [&](double dt) { return classifyStability(withMethod(scene, method, dt), criteria).stable; };
    if (!stable(dt_lo)) return -1.0;
    if (stable(dt_hi)) return std::numeric_limits<double>::infinity();
    while (dt_hi / dt_lo > 1.0 + rel_tol) {
        const double mid = std::sqrt(dt_lo * dt_hi);
        (stable(mid) ? dt_lo : dt_hi) = mid;
    }
    return std::sqrt(dt_lo * dt_hi);
}

namespace {
/// The methods of a sweep, in the order they were run.
std::vector<Method> methodsOf(const StabilityResult& r) {
    std::vector<Method> methods;
    for (const auto& p : r.points)
        if (methods.empty() || methods.back() != p.method) methods.push_back(p.method);
    return methods;
}
}  // namespace

void writeStabilityCsv(const std::string& path, const StabilityResult& r) {
    std::ofstream out(path);
    if (!out) throw InputError(path, "(file)", "cannot write the file");
    out << std::setprecision(10) << "method,k [N/m],dt [s],omega_max_dt [1],stable,steps,energy_growth [E_scale],reason\n";
    for (const StabilityPoint& p : r.points)
        out << methodName(p.method) << "," << p.k << "," << p.dt << "," << p.omega_max * p.dt << "," << (p.verdict.stable ? 1 : 0) << ","
            << p.verdict.steps << "," << p.verdict.energy_growth << ",\"" << p.verdict.reason << "\"\n";
}

void printStabilityTable(std::ostream& out, const StabilityResult& r) {
    out << "stability map of " << r.scene << " (model " << modelName(r.model) << "): '.' stable, '#' unstable, "
        << "'+'/'x' where theory disagrees (stable/unstable measured)\n"
        << "omega_max = " << fmt(r.omega_ref, 4) << " rad/s at k = " << fmt(r.k_ref, 4)
        << " N/m (largest eigenvalue of M^-1 K; scales with sqrt(k))\n";
    for (Method m : methodsOf(r)) {
        std::vector<double> ks, dts;
        for (const auto& p : r.points)
            if (p.method == m) {
                if (std::find(ks.begin(), ks.end(), p.k) == ks.end()) ks.push_back(p.k);
                if (std::find(dts.begin(), dts.end(), p.dt) == dts.end()) dts.push_back(p.dt);
            }
        int agree = 0, cells = 0;
        out << "\n" << methodName(m) << "  (rows: dt [s], columns: k [N/m] from " << fmt(ks.front()) << " to " << fmt(ks.back()) << ")\n";
        for (auto dt = dts.rbegin(); dt != dts.rend(); ++dt) {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%10.3g  ", *dt);
            out << buf;
            for (const auto& p : r.points) {
                if (p.method != m || p.dt != *dt) continue;
                const double limit = theoreticalCriticalDt(p.method, p.omega_max);
                const bool known = limit >= 0.0 && p.omega_max > 0.0;
                const bool theory_stable = p.dt < limit;
                char c = p.verdict.stable ? '.' : '#';
                if (known && p.method != Method::ExplicitEuler) {
                    ++cells;
                    if (theory_stable == p.verdict.stable) ++agree;
                    else c = p.verdict.stable ? '+' : 'x';
                }
                out << c;
            }
            out << "\n";
        }
        switch (m) {
            case Method::ExplicitEuler:
                out << "theory: undamped explicit Euler grows by sqrt(1 + omega^2 dt^2) per step - unstable for every dt; "
                       "the map shows where it grew beyond the energy factor within the run\n";
                break;
            case Method::SymplecticEuler:
            case Method::VelocityVerlet:
                out << "theory: stable iff omega_max dt < 2 (one spring: k < 4 m / dt^2); agrees in " << agree << " of " << cells << " cells\n";
                break;
            case Method::Rk4:
                out << "theory: stable iff omega_max dt < 2 sqrt(2); agrees in " << agree << " of " << cells << " cells\n";
                break;
            case Method::ImplicitEuler:
                out << "theory: stable for every dt (amplitude x 1/sqrt(1 + omega^2 dt^2) per step); agrees in " << agree << " of " << cells << " cells\n";
                break;
            case Method::Pbd:
            case Method::Xpbd: break;
        }
    }
    out << "\nProvot's estimate: k_crit = m pi^2 / dt^2 (the slides print m dt^2 / pi^2 - upside down)";
    if (std::isfinite(r.min_mass)) out << "; here m = " << fmt(r.min_mass) << " kg";
    out << "\n";
}

std::vector<std::string> plotStability(const std::string& dir, const StabilityResult& r) {
    std::vector<std::string> methods;  // names: they name the files and panels
    // One data file per method: k dt stable
    for (Method m : methodsOf(r)) {
        methods.push_back(methodName(m));
        std::ofstream d(dir + "/stability_" + methods.back() + ".dat");
        d << std::setprecision(10) << "# k dt stable\n";
        for (const auto& p : r.points)
            if (p.method == m) d << p.k << " " << p.dt << " " << (p.verdict.stable ? 1 : 0) << "\n";
    }
    const std::string w = fmt(r.omega_ref, 10), kr = fmt(r.k_ref, 10);
    double k_lo = INFINITY, k_hi = 0, dt_lo = INFINITY, dt_hi = 0;
    for (const auto& p : r.points)
        k_lo = std::min(k_lo, p.k), k_hi = std::max(k_hi, p.k), dt_lo = std::min(dt_lo, p.dt), dt_hi = std::max(dt_hi, p.dt);
    std::ostringstream common;
    common << "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\n"
           << "set xlabel 'stiffness k [N/m]'\nset ylabel 'time step {/Symbol D}t [s]'\nset key below maxrows 2 font ',8'\n"
           << "set xrange [" << k_lo / 1.6 << ":" << k_hi * 1.6 << "]\nset yrange [" << dt_lo / 1.6 << ":" << dt_hi * 1.6 << "]\n"
           << "w(k) = " << w << " * sqrt(k / " << kr << ")\n";
    auto panel = [&](const std::string& m) {
        std::ostringstream s;
        const std::string file = "stability_" + m + ".dat";
        std::string title = m;
        for (auto& ch : title) if (ch == '_') ch = ' ';
        s << "set title '" << title << "' noenhanced\n"
          << "plot '" << file << "' using 1:($3 > 0 ? $2 : 1/0) with points pt 7 ps 0.8 lc rgb '#2a9d3a' title 'stable', \\\n"
          << "     '" << file << "' using 1:($3 > 0 ? 1/0 : $2) with points pt 5 ps 0.7 lc rgb '#d62728' title 'unstable', \\\n"
          << "     2 / w(x) with lines lw 2 lc rgb 'black' title '{/Symbol w}_{max}{/Symbol D}t = 2', \\\n"
          << "     2*sqrt(2) / w(x) with lines lw 2 dt 2 lc rgb '#555555' title '{/Symbol w}_{max}{/Symbol D}t = 2{/Symbol \\326}2 (RK4)', \\\n"
          << "     pi / w(x) with lines lw 2 dt 3 lc rgb '#1f5fbf' title 'Provot: {/Symbol w}_{max}{/Symbol D}t = {/Symbol p}'\n";
        return s.str();
    };
    std::vector<std::string> written;
    for (const std::string& m : methods) {
        std::ostringstream s;
        s << "set terminal pngcairo size 640,480 font ',10'\nset output 'stability_" << m << ".png'\n" << common.str() << panel(m);
        if (runGnuplot(dir + "/stability_" + m + ".gp", "cd '" + dir + "'\n" + s.str())) written.push_back(dir + "/stability_" + m + ".png");
    }
    std::ostringstream all;
    const int n = static_cast<int>(methods.size()), cols = std::min(n, 3), rows = (n + cols - 1) / cols;
    all << "cd '" << dir << "'\nset terminal pngcairo size " << 400 * cols << "," << 380 * rows + 30 << " font ',9'\n"
        << "set output 'stability.png'\n" << common.str() << "set multiplot layout " << rows << "," << cols
        << " title '" << modelName(r.model) << ": stability maps (" << r.scene << ")' noenhanced\n";
    for (const std::string& m : methods) all << panel(m);
    all << "unset multiplot\n";
    if (runGnuplot(dir + "/stability.gp", all.str())) written.push_back(dir + "/stability.png");
    return written;
}

CollisionResult collisionSweep(const Scene& scene, const std::vector<double>& dts, const std::vector<int>& iterations, double seconds,
                               const std::function<void(int, int, const std::string&)>& progress) {
    if (scene.colliders.empty()) throw InputError(scene.file, "colliders", "the collision map needs a scene with colliders");
    if (!isPositionBased(scene.solver.method))
        throw InputError(scene.file, "solver.method", "the collision map needs a pbd or xpbd scene (the force-based methods ignore colliders)");
    CollisionResult r{scene.file, scene.solver.dt, scene.solver.iterations, seconds, {}};
    const int total = static_cast<int>(dts.size() * iterations.size());
    for (double dt : dts)
        for (int it : iterations) {
            Scene s = scene;
            s.solver.dt = dt;
            s.solver.iterations = it;
            auto sim = makeSimulation(s);
            RunChecks checks(*sim);
            CollisionPoint p{dt, it, true, false, 0, ""};
            const long long steps = std::max<long long>(1, std::llround(seconds / dt));
            for (long long n = 1; n <= steps && p.stays; ++n) {
                if (std::string stop = checks.step(*sim, n); !stop.empty()) {
                    p = {dt, it, false, true, n, stop};
                    break;
                }
                for (const RunWarning& w : checks.warnings())
                    if (w.kind == WarningKind::FellThrough) p = {dt, it, false, false, w.step, warningHeadline(w, s)};
            }
            r.points.push_back(p);
            if (progress) progress(static_cast<int>(r.points.size()), total, "");
        }
    return r;
}

void writeCollisionCsv(const std::string& path, const CollisionResult& r) {
    std::ofstream out(path);
    if (!out) throw InputError(path, "(file)", "cannot write the file");
    out << std::setprecision(10) << "dt [s],iterations,stays,unstable,step,message\n";
    for (const CollisionPoint& p : r.points)
        out << p.dt << "," << p.iterations << "," << (p.stays ? 1 : 0) << "," << (p.unstable ? 1 : 0) << "," << p.step << ",\"" << p.message << "\"\n";
}

void printCollisionTable(std::ostream& out, const CollisionResult& r) {
    std::vector<int> its;
    for (const auto& p : r.points)
        if (std::find(its.begin(), its.end(), p.iterations) == its.end()) its.push_back(p.iterations);
    out << "collision map of " << r.scene << " over " << fmt(r.seconds) << " s: '.' stays on its colliders, 'F' fell through, '#' unstable; "
        << "the scene's own: dt = " << fmt(r.dt_ref) << " s, " << r.iterations_ref << " iterations\n"
        << "    dt [s]  iterations:";
    for (int i : its) out << " " << i;
    out << "\n";
    double dt = -1;
    size_t col = 0;
    for (const auto& p : r.points) {
        if (p.dt != dt) {
            char buf[40];
            std::snprintf(buf, sizeof buf, "%s%10.4g             ", dt < 0 ? "" : "\n", p.dt);
            out << buf;
            dt = p.dt, col = 0;
        }
        out << std::string(std::to_string(its[col++ % its.size()]).size(), ' ') << (p.unstable ? '#' : p.stays ? '.' : 'F');
    }
    out << "\n";
}

std::string plotCollision(const std::string& dir, const CollisionResult& r) {
    {
        std::ofstream d(dir + "/collision.dat");
        d << std::setprecision(10) << "# dt iterations outcome(0 stays, 1 fell through, 2 unstable)\n";
        for (const auto& p : r.points) d << p.dt << " " << p.iterations << " " << (p.unstable ? 2 : p.stays ? 0 : 1) << "\n";
    }
    std::ostringstream s;
    s << "cd '" << dir << "'\nset terminal pngcairo size 640,480 font ',10'\nset output 'collision.png'\n"
      << "set title 'does the cloth stay on its colliders? (" << r.scene << ", " << fmt(r.seconds) << " s)' noenhanced\n"
      << "set logscale xy\nset xlabel 'time step {/Symbol D}t [s]'\nset ylabel 'solver iterations'\nset key below maxrows 2\n"
      << "set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05\n"
      << "plot 'collision.dat' using 1:($3 == 0 ? $2 : 1/0) with points pt 7 ps 1.4 lc rgb '#2a9d3a' title 'stays', \\\n"
      << "     '' using 1:($3 == 1 ? $2 : 1/0) with points pt 5 ps 1.3 lc rgb '#d62728' title 'fell through', \\\n"
      << "     '' using 1:($3 == 2 ? $2 : 1/0) with points pt 9 ps 1.4 lc rgb '#1f5fbf' title 'unstable', \\\n"
      << "     '-' using 1:2 with points pt 6 ps 2.6 lw 2 lc rgb 'black' title \"the scene's own\"\n"
      << r.dt_ref << " " << r.iterations_ref << "\ne\n";
    return runGnuplot(dir + "/collision.gp", s.str()) ? dir + "/collision.png" : "";
}

}  // namespace clothlab
