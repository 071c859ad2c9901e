// `clothlab run`: one scene, headless, with the report of error metrics beside wall time.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

#include "clothlab/core/input_error.h"
#include "clothlab/io/report.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/sim/mass_spring.h"
#include "clothlab/sim/run.h"
#include "clothlab/study/compare.h"
#include "commands.h"

namespace clothlab::cli {
namespace {
/// `--window T0,T1` (s): two numbers, 0 <= T0 <= T1, and the run (steps of dt) reaches T1.
MetricWindow parseWindow(const std::string& text, double dt, long long steps) {
    const auto bad = [&](const std::string& why) { return InputError("command line", "--window", "\"" + text + "\": " + why); };
    const size_t comma = text.find(',');
    if (comma == std::string::npos) throw bad("expected T0,T1 in s, e.g. --window 2,3");
    MetricWindow w;
    const std::string parts[2] = {text.substr(0, comma), text.substr(comma + 1)};
    double* into[2] = {&w.from, &w.to};
    for (int i = 0; i < 2; ++i) {
        char* end = nullptr;
        *into[i] = std::strtod(parts[i].c_str(), &end);
        if (parts[i].empty() || *end != '\0' || !std::isfinite(*into[i])) throw bad("\"" + parts[i] + "\" is not a number");
    }
    if (w.from < 0 || w.to < w.from) throw bad("needs 0 <= T0 <= T1");
    const double end = static_cast<double>(steps) * dt;
    if (!w.contains(end) && w.to > end) {
        std::ostringstream s;
        s << "the run ends at t = " << end << " s (--steps, --seconds or solver.steps)";
        throw bad(s.str());
    }
    return w;
}
}  // namespace

namespace {

// `run SCENE --compare a,b,...`: the variants advanced together, a sample every 1/100 of the run
// (study/compare.h); a table of the last samples, compare.csv and compare.png.
int runCompare(const std::string& file, const std::vector<std::string>& sets, const std::string& list, long long steps,
               double seconds, std::string out, bool quiet) {
    const Scene scene = loadScene(file, sets);
    const std::vector<CompareVariant> variants = parseCompare(list, file, sets);
    const double T = seconds >= 0 ? seconds : (steps >= 0 ? steps : scene.solver.steps) * scene.solver.dt;
    if (out.empty()) out = "out/compare/" + std::filesystem::path(file).stem().string();
    Comparison c(scene, variants);
    for (const CompareRun& r : c.runs())
        if (!r.sim) throw InputError("command line", "--compare", "\"" + r.variant.label + "\": " + r.message);
    std::cout << "scene   " << scene.file << (scene.description.empty() ? "" : "  — " + scene.description) << "\n"
              << "compare " << variants.size() << " runs to t = " << T << " s, error measure " << c.measure().name << " ["
              << c.measure().unit << "]\n";
    const int samples = 100;
    c.sample();
    for (int k = 1; k <= samples; ++k) {
        c.advanceTo(T * k / samples);
        c.sample();
        if (!quiet && k % 10 == 0) std::cout << "  t = " << T * k / samples << " s\n" << std::flush;
    }
    char buf[256];
    std::snprintf(buf, sizeof buf, "%-28s %10s %10s %12s %14s %14s %12s\n", "run", "t [s]", "wall [s]", "wall/t [s/s]",
                  (c.measure().name + " [" + c.measure().unit + "]").c_str(), "energy [J]", "max_strain");
    std::cout << buf;
    for (const CompareRun& r : c.runs()) {
        const CompareSample& s = r.samples.back();
        std::snprintf(buf, sizeof buf, "%-28s %10.4g %10.4g %12.4g %14.6g %14.6g %12.6g\n", r.variant.label.c_str(), s.t, s.wall,
                      s.t > 0 ? s.wall / s.t : 0.0, s.error, s.energy, s.max_strain);
        std::cout << buf;
        if (!r.message.empty()) std::cout << "  " << r.variant.label << " stopped: " << r.message << "\n";
    }
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec) throw InputError(out, "(folder)", "cannot create the folder (" + ec.message() + ")");
    writeCompareCsv(out + "/compare.csv", c);
    const std::string png = plotCompare(out, c, std::filesystem::path(file).filename().string() + ": " + list);
    std::cout << "wrote " << out << "/compare.csv" << (png.empty() ? "" : " and " + png) << "\n";
    return Ok;
}

}  // namespace

void addRunCommand(CLI::App& app, int& exit_code) {
    struct Options {
        std::string scene, dump, out, state, window, compare;
        std::vector<std::string> sets;
        long long steps = -1, every = 0;
        double seconds = -1;
        bool quiet = false, strict = false;
    };
    auto opt = std::make_shared<Options>();
    CLI::App* cmd = app.add_subcommand("run", "Run a scene headless and print the run report");
    cmd->add_option("scene", opt->scene, "Scene file (JSON)")->required();
    cmd->add_option("--set", opt->sets, "Override a scene field, e.g. --set solver.dt=0.01 (repeatable)");
    auto* steps = cmd->add_option("--steps", opt->steps, "Number of steps (default: solver.steps)")->check(CLI::NonNegativeNumber);
    cmd->add_option("--seconds", opt->seconds, "Simulated time instead of a step count")->check(CLI::NonNegativeNumber)->excludes(steps);
    cmd->add_option("--every", opt->every, "Print a report line every N steps (default: report.every)")->check(CLI::PositiveNumber);
    cmd->add_option("--dump", opt->dump, "Write the final state as CSV (i,x,y,z,vx,vy,vz), 17 significant digits");
    cmd->add_option("--state", opt->state, "Start from the positions and velocities of a state CSV (from --dump or state.csv); time starts at 0");
    cmd->add_option("--out", opt->out, "Folder for report.csv, summary.json and state.csv");
    cmd->add_option("--window", opt->window,
                    "T0,T1: also summarise every metric (min, mean, max) over the states with t in [T0, T1] s, every step");
    cmd->add_option("--compare", opt->compare,
                    "Run 2 to 4 variants side by side, e.g. pbd,xpbd or pbd:iterations=5,pbd:iterations=50; writes compare.csv and "
                    "compare.png to --out (default out/compare/<scene>)");
    cmd->add_flag("--quiet", opt->quiet, "Print only the summary");
    cmd->add_flag("--strict", opt->strict,
                  "A warning (a pinned particle moved, not converged, penetration, fell through a collider, energy growth) stops the run: exit 3 like a blow-up");
    cmd->callback([opt, &exit_code] {
        if (!opt->compare.empty()) {
            if (!opt->state.empty() || !opt->dump.empty() || opt->strict || !opt->window.empty())
                throw InputError("command line", "--compare", "--state, --dump, --strict and --window are for one run, not a comparison");
            exit_code = runCompare(opt->scene, opt->sets, opt->compare, opt->steps, opt->seconds, opt->out, opt->quiet);
            return;
        }
        const Scene scene = loadScene(opt->scene, opt->sets);
        long long steps = opt->steps >= 0 ? opt->steps : scene.solver.steps;
        if (opt->seconds >= 0) steps = static_cast<long long>(std::llround(opt->seconds / scene.solver.dt));
        long long every = opt->every > 0 ? opt->every : scene.report.every;
        if (every <= 0) every = std::max<long long>(1, steps / 10);

        const std::optional<MetricWindow> window =
            opt->window.empty() ? std::nullopt : std::optional<MetricWindow>(parseWindow(opt->window, scene.solver.dt, steps));
        auto sim = makeSimulation(scene);
        if (!opt->state.empty()) {
            if (singleSpringAnalytic(scene))  // its report compares with the exact solution from t = 0
                throw InputError("command line", "--state",
                                 "the single-spring scene is compared with its analytic solution from t = 0; a restarted state has no matching time");
            readStateCsv(opt->state, sim->state());
        }
        std::cout << "scene   " << scene.file << (scene.description.empty() ? "" : "  — " + scene.description) << "\n"
                  << "method  " << methodName(scene.solver.method) << "   dt = " << scene.solver.dt << " s   steps = " << steps
                  << "   particles = " << sim->state().size() << "\n";
        bool header = false;
        const RunResult result = runSimulation(
            *sim, steps, every,
            [&](const ReportRow& row) {
                if (opt->quiet) return;
                if (!header) printReportHeader(std::cout, row), header = true;
                printReportRow(std::cout, row);
            },
            opt->strict, window ? &*window : nullptr);
        printSummary(std::cout, *sim, result);
        if (!opt->out.empty()) {
            std::filesystem::create_directories(opt->out);
            writeReportCsv(opt->out + "/report.csv", result);
            writeSummaryJson(opt->out + "/summary.json", *sim, result);
            writeStateCsv(opt->out + "/state.csv", sim->state());
            std::cout << "wrote " << opt->out << "/{report.csv,summary.json,state.csv}\n";
        }
        if (!opt->dump.empty()) writeStateCsv(opt->dump, sim->state());
        if (result.unstable) {
            std::cerr << "error: " << scene.file << ": solver: " << result.message << "\n";
            exit_code = Unstable;
        } else if (opt->strict && !result.warnings.empty()) {
            // A warning that fired as the run ended (e.g. not converged at the last step): its text is in the summary.
            std::cerr << "error: " << scene.file << ": solver: --strict: " << warningHeadline(result.warnings.front(), scene)
                      << (result.warnings.size() > 1 ? " (and " + std::to_string(result.warnings.size() - 1) + " more warnings in the summary)" : "")
                      << "\n";
            exit_code = Unstable;
        }
    });
}

}  // namespace clothlab::cli
