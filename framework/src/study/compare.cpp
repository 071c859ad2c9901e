#include "clothlab/study/compare.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "clothlab/core/input_error.h"
#include "clothlab/core/not_implemented.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/study/plot.h"

namespace clothlab {

namespace {

std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> out;
    std::string::size_type start = 0;
    while (true) {
        const auto end = s.find(sep, start);
        out.push_back(s.substr(start, end == std::string::npos ? std::string::npos : end - start));
        if (end == std::string::npos) return out;
        start = end + 1;
    }
}

double passSeconds(const Simulation& sim) {
    double s = 0.0;
    for (const auto& p : sim.timer().passes()) s += p.seconds;
    return s;
}

}  // namespace

std::vector<CompareVariant> parseCompare(const std::string& list, const std::string& scene_file, const std::vector<std::string>& sets) {
    const std::vector<std::string> items = split(list, ',');
    if (items.size() < static_cast<size_t>(kCompareMin) || items.size() > static_cast<size_t>(kCompareMax))
        throw InputError("command line", "--compare",
                         "expected " + std::to_string(kCompareMin) + " to " + std::to_string(kCompareMax) +
                             " runs separated by commas, e.g. pbd,xpbd or pbd:iterations=5,pbd:iterations=50 (got \"" + list + "\")");
    std::vector<CompareVariant> out;
    for (const std::string& item : items) {
        const std::vector<std::string> parts = split(item, ':');
        if (parts[0].empty()) throw InputError("command line", "--compare", "an empty run in \"" + list + "\"");
        std::vector<std::string> o = sets;
        o.push_back("solver.method=" + parts[0]);
        for (size_t k = 1; k < parts.size(); ++k) {
            const auto eq = parts[k].find('=');
            if (eq == std::string::npos || eq == 0 || parts[k].find('.') < eq)
                throw InputError("command line", "--compare",
                                 "\"" + item + "\": expected METHOD:key=value with a key of solver (dt, iterations, substeps, ...), got \"" +
                                     parts[k] + "\"");
            o.push_back("solver." + parts[k]);
        }
        try {
            out.push_back({item, loadScene(scene_file, o).solver});
        } catch (const InputError& e) {
            throw InputError("command line", "--compare", "\"" + item + "\": " + e.what());
        }
    }
    return out;
}

std::string compareLabel(const SolverSpec& s, const SolverSpec& base) {
    std::string l = methodName(s.method);
    if (s.dt != base.dt) {
        std::ostringstream o;
        o << s.dt;
        l += ":dt=" + o.str();
    }
    if (isPositionBased(s.method) && s.iterations != base.iterations) l += ":iterations=" + std::to_string(s.iterations);
    if (isPositionBased(s.method) && s.substeps != base.substeps) l += ":substeps=" + std::to_string(s.substeps);
    return l;
}

const char* compareColor(size_t i) {
    static const char* colours[] = {"#0072b2", "#d55e00", "#009e73", "#cc79a7"};
    return colours[i % 4];
}

Scene variantScene(const Scene& base, const CompareVariant& v) {
    Scene s = base;
    s.solver = v.solver;
    return s;
}

CompareMeasure compareMeasure(const Scene& scene, const std::vector<Metric>& metrics) {
    const auto find = [&](const std::string& name) -> const Metric* {
        for (const Metric& m : metrics)
            if (m.name == name) return &m;
        return nullptr;
    };
    if (!scene.view.error.empty()) {
        if (const Metric* m = find(scene.view.error)) return {m->name, m->unit};
        std::string names;
        for (const Metric& m : metrics) names += (names.empty() ? "" : ", ") + m.name;
        throw InputError(scene.file, "view.error", "\"" + scene.view.error + "\" is not a measure of this scene (its measures: " + names + ")");
    }
    for (const char* name : {"error", "catenary_error", "rms_strain", "energy_drift"})
        if (const Metric* m = find(name)) return {m->name, m->unit};
    return {"energy_drift", "J"};
}

Comparison::Comparison(const Scene& base, std::vector<CompareVariant> variants,
                       std::function<std::unique_ptr<Simulation>(const Scene&)> factory) {
    bool measured = false;
    for (CompareVariant& v : variants) {
        CompareRun r;
        r.scene = variantScene(base, v);
        r.variant = std::move(v);
        try {
            r.sim = factory ? factory(r.scene) : makeSimulation(r.scene);
        } catch (const std::exception& e) {
            r.message = e.what();
        }
        if (r.sim && !measured) {
            try {
                measure_ = compareMeasure(r.scene, r.sim->metrics());
                measured = true;
            } catch (const NotImplemented&) {  // a stub in the measures: the run says so at its first step
            }
        }
        runs_.push_back(std::move(r));
    }
}

void Comparison::step(CompareRun& r) {
    try {
        if (!r.checks) r.checks = std::make_unique<RunChecks>(*r.sim);
        const std::string stop = r.checks->step(*r.sim, ++r.steps);
        if (!stop.empty()) r.message = stop;
    } catch (const NotImplemented& e) {
        r.message = e.what();
        throw;
    }
    r.wall = passSeconds(*r.sim);
}

void Comparison::advanceTo(double t, double budget, const std::function<void(CompareRun&)>& before) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    while (std::chrono::duration<double>(Clock::now() - start).count() < budget) {
        CompareRun* behind = nullptr;  // the run furthest behind that has not reached t
        for (CompareRun& r : runs_)
            if (!r.stopped() && r.sim->state().t < t - 1e-9 * std::max(1.0, std::abs(t)) &&
                (!behind || r.sim->state().t < behind->sim->state().t))
                behind = &r;
        if (!behind) return;
        if (before) before(*behind);
        step(*behind);
    }
}

void Comparison::stepRun(size_t i) {
    if (i < runs_.size() && !runs_[i].stopped()) step(runs_[i]);
}

void Comparison::sample() {
    for (CompareRun& r : runs_) {
        if (!r.sim) continue;
        if (r.stopped() && !r.samples.empty() && r.samples.back().steps == r.steps) continue;  // its last sample is taken
        CompareSample s;
        s.t = r.sim->state().t;
        s.wall = r.wall;
        s.steps = r.steps;
        try {
            for (const Metric& m : r.sim->metrics()) {
                if (m.name == measure_.name) s.error = m.value;
                if (m.name == "energy") s.energy = m.value;
                if (m.name == "max_strain") s.max_strain = m.value;
            }
        } catch (const NotImplemented&) {
            continue;  // a stub in the measures: no sample (the step says why)
        }
        if (!r.samples.empty() && s.steps > r.samples.back().steps)
            s.step_ms = 1e3 * (s.wall - r.samples.back().wall) / double(s.steps - r.samples.back().steps);
        else if (!r.samples.empty())
            s.step_ms = r.samples.back().step_ms;
        r.samples.push_back(s);
    }
}

double Comparison::time() const {
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    for (const CompareRun& r : runs_) {
        if (!r.sim) continue;
        hi = std::max(hi, r.sim->state().t);
        if (!r.stopped()) lo = std::min(lo, r.sim->state().t);
    }
    return std::isfinite(lo) ? lo : hi;
}

void writeCompareCsv(const std::string& path, const Comparison& c) {
    std::ofstream out(path);
    if (!out) throw InputError(path, "(file)", "cannot write the file");
    out << std::setprecision(17);
    out << "method,t [s],wall [s]," << c.measure().name << " [" << c.measure().unit << "],energy [J],max_strain [1]\n";
    size_t most = 0;
    for (const CompareRun& r : c.runs()) most = std::max(most, r.samples.size());
    const auto num = [&](double v) {
        if (std::isnan(v)) out << "nan";
        else out << v;
    };
    for (size_t k = 0; k < most; ++k)
        for (const CompareRun& r : c.runs()) {
            if (k >= r.samples.size()) continue;
            const CompareSample& s = r.samples[k];
            out << r.variant.label << ",";
            num(s.t), out << ",";
            num(s.wall), out << ",";
            num(s.error), out << ",";
            num(s.energy), out << ",";
            num(s.max_strain), out << "\n";
        }
    if (!out) throw InputError(path, "(file)", "cannot write the file");
}

std::string plotCompare(const std::string& dir, const Comparison& c, const std::string& title) {
    const CompareMeasure& m = c.measure();
    // compare.dat: one block per run (gnuplot's `index i`), columns t, wall, measure, energy, max strain.
    {
        std::ofstream d(dir + "/compare.dat");
        if (!d) throw InputError(dir + "/compare.dat", "(file)", "cannot write the file");
        d << std::setprecision(10);
        for (const CompareRun& r : c.runs()) {
            d << "# " << r.variant.label << ": t [s], wall [s], " << m.name << " [" << m.unit << "], energy [J], max_strain [1]\n";
            for (const CompareSample& x : r.samples) d << x.t << " " << x.wall << " " << x.error << " " << x.energy << " " << x.max_strain << "\n";
            d << "\n\n";
        }
    }
    // The energy axis spans the runs that did not stop (a blow-up would flatten the others), when some did.
    double lo = INFINITY, hi = -INFINITY;
    bool stopped = false, strain = false;  // a spring has no edges: no strain panel
    for (const CompareRun& r : c.runs()) {
        stopped = stopped || r.stopped();
        for (const CompareSample& x : r.samples) {
            strain = strain || std::isfinite(x.max_strain);
            if (!r.stopped() && std::isfinite(x.energy)) lo = std::min(lo, x.energy), hi = std::max(hi, x.energy);
        }
    }
    std::ostringstream s;
    s << "cd '" << dir << "'\nset terminal pngcairo size 1280,800 font ',11'\nset output 'compare.png'\n"
      << "set grid\nset key top right font ',10' noenhanced\nset multiplot layout 2,2 title '" << title << "' noenhanced\n";
    const auto plot = [&](const std::string& using_, const std::string& style) {
        s << "plot ";
        for (size_t i = 0; i < c.runs().size(); ++i)
            s << (i ? ", \\\n     " : "") << "'compare.dat' index " << i << " using " << using_ << " with " << style << " lw 2 lc rgb '"
              << compareColor(i) << "' title '" << c.runs()[i].variant.label << "'";
        s << "\n";
    };
    const std::string ylabel = m.name + " [" + m.unit + "]";
    s << "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\nset xlabel 'wall time per simulated second [s/s]'\n"
      << "set ylabel '" << ylabel << "' noenhanced\nset title 'error against run time: left is cheaper, lower is more accurate'\n";
    plot("($1 > 0 ? $2/$1 : NaN):(abs($3))", "linespoints pt 7 ps 0.5");
    s << "unset logscale x\nset format x '%g'\nset xlabel 'simulated time t [s]'\nset title '" << m.name << " against simulated time' noenhanced\n";
    plot("1:(abs($3))", "lines");
    s << "unset logscale y\nset format y '%g'\nset ylabel 'energy [J]'\nset title 'energy" << (stopped ? " (of the runs that did not stop)" : "") << "'\n";
    if (stopped && std::isfinite(lo)) s << "set yrange [" << lo - 0.1 * (hi - lo + 1e-9) << ":" << hi + 0.1 * (hi - lo + 1e-9) << "]\n";
    plot("1:4", "lines");
    s << "set autoscale y\n";
    if (strain) {
        s << "set ylabel 'max strain [1]'\nset title 'max strain'\n";
        plot("1:5", "lines");
    }
    s << "unset multiplot\n";
    return runGnuplot(dir + "/compare.gp", s.str()) ? dir + "/compare.png" : "";
}

}  // namespace clothlab
