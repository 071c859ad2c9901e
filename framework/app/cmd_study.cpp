// `clothlab study stability|precision|sag SCENE` and `clothlab study extremes`: sweeps with CSV, PNG plots and a printed table.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "clothlab/core/input_error.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/study/extremes.h"
#include "clothlab/study/precision.h"
#include "clothlab/study/sag.h"
#include "clothlab/study/stability.h"
#include "clothlab/study/theory.h"
#include "commands.h"

namespace clothlab::cli {
namespace {

/// Progress on stderr: an updating line on a terminal, a line per 10 % otherwise.
std::function<void(int, int, const std::string&)> progressPrinter(const std::string& what) {
    const bool tty = isatty(2);
    return [tty, what, last = -1](int done, int total, const std::string& method) mutable {
        const int percent = total > 0 ? 100 * done / total : 100;
        if (tty) {
            std::cerr << "\r" << what << ": " << done << "/" << total << " runs (" << percent << " %), " << method << "          "
                      << (done == total ? "\n" : "") << std::flush;
        } else if (percent / 10 != last / 10 || done == total) {
            std::cerr << what << ": " << done << "/" << total << " runs (" << percent << " %)\n";
        }
        last = percent;
    };
}

std::vector<Method> splitMethods(const std::string& list) {
    std::vector<Method> out;
    std::string cur;
    for (char c : list + ",") {
        if (c == ',') {
            if (!cur.empty()) {
                const std::optional<Method> m = parseMethod(cur);
                if (!m) throw InputError("command line", "--methods", "unknown method \"" + cur + "\"");
                out.push_back(*m);
            }
            cur.clear();
        } else if (c != ' ') {
            cur += c;
        }
    }
    if (out.empty()) throw InputError("command line", "--methods", "no method given");
    return out;
}

std::string defaultOut(const std::string& scene, const std::string& kind) {
    return "out/study/" + std::filesystem::path(scene).stem().string() + "-" + kind;
}

/// Comma-separated words, blanks dropped.
std::vector<std::string> splitWords(const std::string& list) {
    std::vector<std::string> out;
    std::string cur;
    for (char c : list + ",") {
        if (c == ',') {
            if (!cur.empty()) out.push_back(cur);
            cur.clear();
        } else if (c != ' ') {
            cur += c;
        }
    }
    return out;
}

/// Comma-separated positive integers (the budgets of a position-based sweep).
std::vector<int> splitInts(const std::string& list, const char* name) {
    std::vector<int> out;
    std::string cur;
    for (char c : list + ",") {
        if (c == ',') {
            if (!cur.empty()) {
                size_t used = 0;
                int v = 0;
                try {
                    v = std::stoi(cur, &used);
                } catch (const std::exception&) {
                    used = 0;
                }
                if (used != cur.size() || v < 1 || v > 100000)
                    throw InputError("command line", name, "\"" + cur + "\" is not a whole number in [1, 100000]");
                out.push_back(v);
            }
            cur.clear();
        } else if (c != ' ') {
            cur += c;
        }
    }
    if (out.empty()) throw InputError("command line", name, "no value given");
    return out;
}

void checkRange(const char* name, double lo, double hi, int count) {
    if (!(lo > 0.0) || !(hi >= lo)) throw InputError("command line", name, "needs 0 < min <= max");
    if (count < 1 || count > 1000) throw InputError("command line", name, "count must be between 1 and 1000");
}

}  // namespace

void addStudyCommand(CLI::App& app, int& exit_code) {
    CLI::App* study = app.add_subcommand("study", "Stability maps, error-vs-run-time studies (force-based: dt sweeps; pbd/xpbd: iterations and substeps), PBD-vs-XPBD sag");
    study->require_subcommand(1);

    // ---- study stability ----------------------------------------------------------------------
    struct StabilityCli {
        std::string scene, out, methods;
        std::vector<std::string> sets;
        double k_min = NAN, k_max = NAN, dt_min = NAN, dt_max = NAN, factor = 100;
        int k_count = 13, dt_count = 13;
        long long steps = 1000;
        bool collision = false;
        std::string iterations = "1,2,5,10,20,50";
        double seconds = -1;
    };
    auto so = std::make_shared<StabilityCli>();
    CLI::App* st = study->add_subcommand("stability", "Sweep stiffness k and time step dt per integrator; CSV, PNG maps, table");
    st->add_option("scene", so->scene, "Scene file (JSON)")->required();
    st->add_option("--set", so->sets, "Override a scene field (repeatable)");
    st->add_option("--methods", so->methods, "Comma-separated methods (default: all force-based)");
    st->add_option("--k-min", so->k_min, "Smallest stiffness, N/m (default: scene k / 100)");
    st->add_option("--k-max", so->k_max, "Largest stiffness, N/m (default: scene k * 10^4)");
    st->add_option("--k-count", so->k_count, "Number of stiffness values (log-spaced)");
    st->add_option("--dt-min", so->dt_min, "Smallest time step, s (default: scene dt / 100)");
    st->add_option("--dt-max", so->dt_max, "Largest time step, s (default: scene dt * 100)");
    auto* dtCount = st->add_option("--dt-count", so->dt_count, "Number of time steps (log-spaced)");
    st->add_option("--steps", so->steps, "Steps per run")->check(CLI::PositiveNumber);
    st->add_option("--energy-factor", so->factor, "Unstable if the energy rises by more than this many E_scale")->check(CLI::PositiveNumber);
    st->add_option("--out", so->out, "Output folder (default: out/study/<scene>-stability)");
    st->add_flag("--collision", so->collision,
                 "The collision axis instead (pbd/xpbd scene with colliders): dt x iterations, does the cloth stay on its colliders; "
                 "dt from scene dt / 4 to scene dt * 8 (6 values) unless given; collision.csv, collision.png");
    st->add_option("--iterations", so->iterations, "--collision: comma-separated solver iterations");
    st->add_option("--seconds", so->seconds, "--collision: simulated time per run, s (default: the scene's steps x dt)")->check(CLI::PositiveNumber);
    st->callback([so, dtCount] {
        const Scene scene = loadScene(so->scene, so->sets);
        if (so->collision) {
            const double dt_min = !std::isnan(so->dt_min) ? so->dt_min : scene.solver.dt / 4;
            const double dt_max = !std::isnan(so->dt_max) ? so->dt_max : scene.solver.dt * 8;
            const int count = dtCount->count() > 0 ? so->dt_count : 6;
            checkRange("--dt-min/--dt-max/--dt-count", dt_min, dt_max, count);
            const double seconds = so->seconds > 0 ? so->seconds : scene.solver.steps * scene.solver.dt;
            const std::string out = so->out.empty() ? defaultOut(so->scene, "collision") : so->out;
            std::filesystem::create_directories(out);
            const std::vector<int> its = splitInts(so->iterations, "--iterations");
            std::cout << "collision map of " << scene.file << ": " << count << " dt in [" << dt_min << ", " << dt_max << "] s x " << its.size()
                      << " iterations, " << seconds << " s simulated per run\n";
            const CollisionResult r = collisionSweep(scene, logSpace(dt_min, dt_max, count), its, seconds, progressPrinter("collision"));
            printCollisionTable(std::cout, r);
            writeCollisionCsv(out + "/collision.csv", r);
            std::cout << "wrote " << out << "/collision.csv\n";
            const std::string png = plotCollision(std::filesystem::absolute(out).string(), r);
            if (!png.empty()) std::cout << "wrote " << png << "\n";
            return;
        }
        StabilityOptions o;
        if (!so->methods.empty()) o.methods = splitMethods(so->methods);
        const double k = sceneStiffness(scene);
        o.k_min = !std::isnan(so->k_min) ? so->k_min : k / 100;
        o.k_max = !std::isnan(so->k_max) ? so->k_max : k * 1e4;
        o.dt_min = !std::isnan(so->dt_min) ? so->dt_min : scene.solver.dt / 100;
        o.dt_max = !std::isnan(so->dt_max) ? so->dt_max : scene.solver.dt * 100;
        o.k_count = so->k_count, o.dt_count = so->dt_count;
        checkRange("--k-min/--k-max/--k-count", o.k_min, o.k_max, o.k_count);
        checkRange("--dt-min/--dt-max/--dt-count", o.dt_min, o.dt_max, o.dt_count);
        o.criteria.steps = so->steps;
        o.criteria.energy_factor = so->factor;
        o.progress = progressPrinter("stability");
        const std::string out = so->out.empty() ? defaultOut(so->scene, "stability") : so->out;
        std::filesystem::create_directories(out);
        std::cout << "stability study of " << scene.file << ": " << o.methods.size() << " methods x " << o.k_count << " k in [" << o.k_min
                  << ", " << o.k_max << "] N/m x " << o.dt_count << " dt in [" << o.dt_min << ", " << o.dt_max << "] s, " << o.criteria.steps
                  << " steps per run\n";
        const StabilityResult r = stabilitySweep(scene, o);
        printStabilityTable(std::cout, r);
        // The measured critical step at the scene's own k, against theory (bisection).
        for (Method m : o.methods) {
            const double theory = theoreticalCriticalDt(m, r.omega_ref);
            if (!(theory > 0.0) || !std::isfinite(theory)) continue;
            const double measured = measureCriticalDt(scene, m, theory / 10, theory * 10, o.criteria);
            std::printf("%-18s critical dt at k = %g N/m: measured %.4g s, theory %.4g s (ratio %.3f)\n", methodName(m), r.k_ref,
                        measured, theory, measured / theory);
        }
        writeStabilityCsv(out + "/stability.csv", r);
        std::cout << "wrote " << out << "/stability.csv\n";
        for (const std::string& png : plotStability(std::filesystem::absolute(out).string(), r)) std::cout << "wrote " << png << "\n";
    });

    // ---- study precision ----------------------------------------------------------------------
    struct PrecisionCli {
        std::string scene, out, methods, reference_method, budgets = "1,2,5,10,20,50,100", sweeps = "iterations,substeps";
        std::vector<std::string> sets;
        double dt_min = NAN, dt_max = NAN, end_time = 1.0, reference_dt = 0;
        int dt_count = 7, reference_substeps = 1000, reference_iterations = 1;
    };
    auto po = std::make_shared<PrecisionCli>();
    CLI::App* pr = study->add_subcommand("precision", "Error at a fixed end time against wall time per method and dt; CSV, PNG, table");
    pr->add_option("scene", po->scene, "Scene file (JSON)")->required();
    pr->add_option("--set", po->sets, "Override a scene field (repeatable)");
    pr->add_option("--methods", po->methods, "Comma-separated methods (default: all force-based; pbd,xpbd for a pbd/xpbd scene)");
    pr->add_option("--dt-min", po->dt_min, "Smallest time step, s (default: scene dt / 10)");
    pr->add_option("--dt-max", po->dt_max, "Largest time step, s (default: scene dt * 10)");
    pr->add_option("--dt-count", po->dt_count, "Number of time steps (log-spaced)");
    pr->add_option("--end-time", po->end_time, "Simulated time T at which the error is measured, s")->check(CLI::PositiveNumber);
    pr->add_option("--reference-method", po->reference_method, "Method of the reference run (no analytic solution; default rk4, xpbd for a pbd/xpbd scene)");
    pr->add_option("--reference-dt", po->reference_dt, "Time step of the reference run, s (default: dt-min / 8)");
    pr->add_option("--budgets", po->budgets, "pbd/xpbd: comma-separated iterations or substeps per frame to sweep");
    pr->add_option("--sweeps", po->sweeps, "pbd/xpbd: what the budget sets: iterations, substeps or both (comma-separated)");
    pr->add_option("--reference-substeps", po->reference_substeps, "pbd/xpbd reference: substeps per frame")->check(CLI::Range(1, 1000000));
    pr->add_option("--reference-iterations", po->reference_iterations, "pbd/xpbd reference: iterations per substep")->check(CLI::Range(1, 10000));
    pr->add_option("--out", po->out, "Output folder (default: out/study/<scene>-precision)");
    pr->callback([po] {
        const Scene scene = loadScene(po->scene, po->sets);
        PrecisionOptions o;
        const bool positionBased = isPositionBased(scene.solver.method);
        if (positionBased) o.methods = {Method::Pbd, Method::Xpbd};
        if (!po->methods.empty()) o.methods = splitMethods(po->methods);
        o.budgets = splitInts(po->budgets, "--budgets");
        o.sweeps.clear();
        for (const std::string& sw : splitWords(po->sweeps)) {
            if (sw != "iterations" && sw != "substeps") throw InputError("command line", "--sweeps", "unknown sweep \"" + sw + "\" (iterations or substeps)");
            o.sweeps.push_back(sw);
        }
        if (o.sweeps.empty()) throw InputError("command line", "--sweeps", "no sweep given");
        o.reference_substeps = po->reference_substeps;
        o.reference_iterations = po->reference_iterations;
        o.dt_min = !std::isnan(po->dt_min) ? po->dt_min : scene.solver.dt / 10;
        o.dt_max = !std::isnan(po->dt_max) ? po->dt_max : scene.solver.dt * 10;
        o.dt_count = po->dt_count;
        checkRange("--dt-min/--dt-max/--dt-count", o.dt_min, o.dt_max, o.dt_count);
        if (o.dt_max > po->end_time) throw InputError("command line", "--dt-max", "must not exceed --end-time");
        if (scene.solver.dt > po->end_time) throw InputError("command line", "--end-time", "must not be shorter than the scene's solver.dt");
        o.end_time = po->end_time;
        o.reference_method = splitMethods(!po->reference_method.empty() ? po->reference_method : positionBased ? "xpbd" : "rk4").front();
        o.reference_dt = po->reference_dt;
        o.progress = progressPrinter("precision");
        const std::string out = po->out.empty() ? defaultOut(po->scene, "precision") : po->out;
        std::filesystem::create_directories(out);
        if (positionBased)
            std::cout << "precision study of " << scene.file << ": " << o.methods.size() << " methods x " << o.sweeps.size() << " sweeps x "
                      << o.budgets.size() << " budgets (" << po->budgets << ") at frame dt = " << scene.solver.dt << " s, error at T = " << o.end_time
                      << " s\n";
        else
            std::cout << "precision study of " << scene.file << ": " << o.methods.size() << " methods x " << o.dt_count << " dt in [" << o.dt_min
                      << ", " << o.dt_max << "] s, error at T = " << o.end_time << " s\n";
        PrecisionResult r = precisionStudy(scene, o);
        for (const std::string& set : po->sets) r.scene += " --set " + set;  // tables and plot titles name the overrides
        printPrecisionTable(std::cout, r);
        writePrecisionCsv(out + "/precision.csv", r);
        std::cout << "wrote " << out << "/precision.csv\n";
        for (const std::string& png : plotPrecision(std::filesystem::absolute(out).string(), r)) std::cout << "wrote " << png << "\n";
    });

    // ---- study extremes (extremes.h) -----------------------------------------------------------
    struct ExtremesCli {
        std::string out = "out/study/extremes", scenes = "scenes", methods, ks, dts, iterations, compliances;
        long long steps = 100;
    };
    auto ex = std::make_shared<ExtremesCli>();
    CLI::App* xs = study->add_subcommand("extremes", "The extreme matrix for every method: stable / reported (with the step) / silently wrong; "
                                                     "markdown table, CSV, PNG; exit 3 if any cell is silently wrong");
    xs->add_option("--scenes", ex->scenes, "Folder with the shipped scenes the cases start from");
    xs->add_option("--methods", ex->methods, "Comma-separated methods (default: all)");
    xs->add_option("--k", ex->ks, "Comma-separated stiffnesses of the force-based cases, N/m (default 1, 10, ..., 1e9)");
    xs->add_option("--dt", ex->dts, "Comma-separated time steps, s (default 1e-5, 1e-4, ..., 1)");
    xs->add_option("--iterations", ex->iterations, "Comma-separated PBD iterations (default 1, 3, 10, 30, 100, 300, 1000)");
    xs->add_option("--compliance", ex->compliances, "Comma-separated XPBD compliances, m/N (default 0, 1e-9, 1e-6, 1e-3, 1)");
    xs->add_option("--steps", ex->steps, "Steps per run")->check(CLI::PositiveNumber);
    xs->add_option("--out", ex->out, "Output folder (default: out/study/extremes)");
    xs->callback([ex, &exit_code] {
        ExtremesOptions o;
        auto numbers = [](const std::string& list, const char* name, bool positive) {
            std::vector<double> v;
            for (const std::string& w : splitWords(list)) {
                char* end = nullptr;
                const double x = std::strtod(w.c_str(), &end);
                if (end == w.c_str() || *end != '\0' || !std::isfinite(x) || x < 0 || (positive && x == 0))
                    throw InputError("command line", name, "\"" + w + "\" is not a " + (positive ? "positive" : "non-negative") + " number");
                v.push_back(x);
            }
            if (v.empty()) throw InputError("command line", name, "no value given");
            return v;
        };
        if (!ex->methods.empty()) o.methods = splitMethods(ex->methods);
        if (!ex->ks.empty()) o.ks = numbers(ex->ks, "--k", true);
        if (!ex->dts.empty()) o.dts = numbers(ex->dts, "--dt", true);
        if (!ex->iterations.empty()) {
            o.iterations.clear();
            for (int i : splitInts(ex->iterations, "--iterations")) o.iterations.push_back(i);
        }
        if (!ex->compliances.empty()) o.compliances = numbers(ex->compliances, "--compliance", false);
        o.steps = ex->steps;
        o.progress = progressPrinter("extremes");
        const std::vector<ExtremeCase> cases = extremeCases(ex->scenes);
        loadScene(ex->scenes + "/spring.json");  // a wrong --scenes: one clear error before any run
        std::filesystem::create_directories(ex->out);
        std::cout << "extremes study: " << cases.size() << " cases x the methods that apply, " << o.steps << " steps per run\n";
        const std::vector<ExtremeCell> cells = extremesStudy(cases, o);
        std::string command = "./lab study extremes";
        if (o.steps != 100) command += " --steps " + std::to_string(o.steps);
        for (const auto& [flag, value] : {std::pair<const char*, std::string>{"--methods", ex->methods}, {"--k", ex->ks}, {"--dt", ex->dts},
                                          {"--iterations", ex->iterations}, {"--compliance", ex->compliances}})
            if (!value.empty()) command += std::string(" ") + flag + " " + value;
        writeExtremesMarkdown(std::cout, cells, command);
        {
            std::ofstream md(ex->out + "/extremes.md");
            if (!md) throw InputError(ex->out + "/extremes.md", "(file)", "cannot write the file");
            writeExtremesMarkdown(md, cells, command);
        }
        writeExtremesCsv(ex->out + "/extremes.csv", cells);
        std::cout << "wrote " << ex->out << "/extremes.md\nwrote " << ex->out << "/extremes.csv\n";
        const std::string png = plotExtremes(std::filesystem::absolute(ex->out).string(), cells);
        if (!png.empty()) std::cout << "wrote " << png << "\n";
        for (const ExtremeCell& c : cells)
            if (c.outcome == ExtremeOutcome::SilentlyWrong) {
                std::cerr << "error: extremes: silently wrong: " << c.case_name << ", " << methodName(c.method) << ": " << c.message << "\n";
                exit_code = Unstable;
                break;
            }
    });

    // ---- study sag (sag.h) ---------------------------------------------------------------------
    struct SagCli {
        std::string scene, out, iterations = "1,2,5,10,20,50,100", substeps = "1,10";
        std::vector<std::string> sets;
        double compliance = 0.01, seconds = 3.0;
    };
    auto ga = std::make_shared<SagCli>();
    CLI::App* sg = study->add_subcommand("sag", "Static sag of a hanging cloth against the iterations, PBD vs XPBD; CSV, PNG, table");
    sg->add_option("scene", ga->scene, "Scene file (JSON) with a hanging pbd/xpbd cloth, e.g. scenes/pbd_curtain.json")->required();
    sg->add_option("--set", ga->sets, "Override a scene field (repeatable)");
    sg->add_option("--iterations", ga->iterations, "Comma-separated solver iterations to sweep");
    sg->add_option("--compliance", ga->compliance, "XPBD compliance of the distance constraints, m/N")->check(CLI::NonNegativeNumber);
    sg->add_option("--xpbd-substeps", ga->substeps, "Comma-separated substep counts, one XPBD series each");
    sg->add_option("--seconds", ga->seconds, "Simulated time before the sag is measured, s")->check(CLI::PositiveNumber);
    sg->add_option("--out", ga->out, "Output folder (default: out/study/<scene>-sag)");
    sg->callback([ga] {
        SagOptions o;
        o.iterations = splitInts(ga->iterations, "--iterations");
        o.xpbd_substeps = splitInts(ga->substeps, "--xpbd-substeps");
        o.compliance = ga->compliance;
        o.seconds = ga->seconds;
        if (!isPositionBased(loadScene(ga->scene, ga->sets).solver.method))
            throw InputError(ga->scene, "solver.method", "the sag study needs a pbd or xpbd scene");
        const std::string out = ga->out.empty() ? defaultOut(ga->scene, "sag") : ga->out;
        std::filesystem::create_directories(out);
        const SagResult r = sagStudy(ga->scene, ga->sets, o);
        printSagTable(std::cout, r);
        for (const std::string& f : writeSag(std::filesystem::absolute(out).string(), r)) std::cout << "wrote " << f << "\n";
    });
}

}  // namespace clothlab::cli
