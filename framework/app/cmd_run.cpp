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

void addRunCommand(CLI::App& app, int& exit_code) {
    struct Options {
        std::string scene, dump, out, state, window;
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
    cmd->add_flag("--quiet", opt->quiet, "Print only the summary");
    cmd->add_flag("--strict", opt->strict,
                  "A warning (a pinned particle moved, not converged, penetration, fell through a collider, energy growth) stops the run: exit 3 like a blow-up");
    cmd->callback([opt, &exit_code] {
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
