/// @file compare.h
/// @brief Methods side by side: two to four variants of one scene (methods, or parameter sets of one
/// method) run on identical copies, advanced together in simulated time and sampled together: the
/// scene's error measure against the wall time each run needed. `clothlab run SCENE --compare a,b`
/// writes compare.csv and compare.png; the app (`./lab gui SCENE --compare a,b`) shows the runs in a
/// split view with the same plots live.
#pragma once
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "clothlab/core/scene.h"
#include "clothlab/sim/run.h"
#include "clothlab/sim/simulation.h"

namespace clothlab {

/// The fewest runs of a comparison.
constexpr int kCompareMin = 2;
/// The most runs of a comparison (the app's split view: two or three in a row, four as 2 x 2).
constexpr int kCompareMax = 4;

/// One variant of a comparison: its label and its solver; everything else is the scene's.
struct CompareVariant {
    std::string label;  ///< the item as given, e.g. "pbd:iterations=5"
    SolverSpec solver;  ///< the scene's solver with the item's method and settings
};

/// Parses the list of `--compare`: items separated by commas, each `METHOD` or
/// `METHOD:key=value[:key=value...]` with keys of the scene's `solver` object (dt, iterations,
/// substeps, kernel, threads, thickness), e.g. `pbd:iterations=5,pbd:iterations=50`,
/// `pbd,xpbd`, `explicit_euler,symplectic_euler,implicit_euler`. Each item is checked by loading the
/// scene with its settings as `--set solver.key=value` overrides, so a bad value gets the loader's message.
/// @param list        the list, e.g. "pbd,xpbd"
/// @param scene_file  the scene file
/// @param sets        the `--set` overrides of the command line (applied before the item's)
/// @throws InputError `command line: --compare: <reason>` for fewer than kCompareMin or more than
///                    kCompareMax items, an empty item or one that is not key=value; the loader's error for a bad value
std::vector<CompareVariant> parseCompare(const std::string& list, const std::string& scene_file,
                                         const std::vector<std::string>& sets = {});

/// The label of a solver against the scene's, in the syntax of parseCompare(): the method, then
/// `:key=value` for each of dt, iterations and substeps (the last two for pbd and xpbd) that differs,
/// e.g. "pbd:iterations=50" (the app names a run the user changed this way).
/// @param s     the run's solver
/// @param base  the scene's solver
std::string compareLabel(const SolverSpec& s, const SolverSpec& base);

/// The colour of run i in the app's labels and plots and in compare.png, as "#rrggbb": the Okabe–Ito
/// colours blue, vermillion, bluish green, reddish purple (told apart with the common colour-vision deficiencies).
/// @param i  the run (taken modulo 4)
const char* compareColor(size_t i);

/// The scene one variant runs: `base` with the variant's solver.
/// @param base  the scene
/// @param v     the variant
Scene variantScene(const Scene& base, const CompareVariant& v);

/// The error measure of a comparison: a metric of the run report, with its unit.
struct CompareMeasure {
    std::string name;  ///< metric name, e.g. "rms_strain"
    std::string unit;  ///< its unit, e.g. "1"
};

/// The scene's error measure among `metrics` (Simulation::metrics()): `view.error` when the scene names
/// one, else the first there of `error` (the distance to the analytic solution), `catenary_error`,
/// `rms_strain`, `energy_drift`.
/// @param scene    the scene
/// @param metrics  the metrics of one of its runs
/// @throws InputError `<scene>: view.error: ...` when the scene names a metric its runs do not report
CompareMeasure compareMeasure(const Scene& scene, const std::vector<Metric>& metrics);

/// One sample of one run.
struct CompareSample {
    double t = 0.0;       ///< simulated time, s
    double wall = 0.0;    ///< wall time of the run's steps so far, s (CompareRun::wall)
    long long steps = 0;  ///< steps so far
    double error = std::numeric_limits<double>::quiet_NaN();       ///< the measure (CompareMeasure), its unit
    double energy = std::numeric_limits<double>::quiet_NaN();      ///< energy, J
    double max_strain = std::numeric_limits<double>::quiet_NaN();  ///< max edge strain, 1 (NaN: no edges)
    double step_ms = std::numeric_limits<double>::quiet_NaN();     ///< wall time per step since the last sample, ms
};

/// One run of a comparison.
struct CompareRun {
    CompareVariant variant;            ///< label and solver
    Scene scene;                       ///< the scene it runs (variantScene())
    std::unique_ptr<Simulation> sim;   ///< the simulation (null when it could not be built: `message` says why)
    std::unique_ptr<RunChecks> checks; ///< the run checks (made at its first step)
    long long steps = 0;               ///< steps done
    /// Wall time of its steps, s: the sum of its passes (Simulation::timer()), so the run checks, the
    /// measures and the drawing are not counted, nor the other runs.
    double wall = 0.0;
    std::string message;               ///< why it stopped: "unstable at step N ..." or "not implemented: ..." ("" while it runs)
    std::vector<CompareSample> samples;  ///< every sample so far
    /// True once it cannot go on (no simulation, stopped unstable, a stub hit).
    bool stopped() const { return !sim || !message.empty(); }
};

/// Two to four runs of one scene, advanced together.
class Comparison {
public:
    /// Builds the runs (a run whose simulation cannot be built keeps the reason in its message).
    /// @param base      the scene
    /// @param variants  the variants (parseCompare()); one is allowed (the app's single run)
    /// @param factory   builds a simulation (default makeSimulation; tests put stand-ins here)
    Comparison(const Scene& base, std::vector<CompareVariant> variants,
               std::function<std::unique_ptr<Simulation>(const Scene&)> factory = {});

    /// Steps every run that can go on until its simulated time reaches t (each with its own Δt, so it
    /// may pass t by less than its Δt), one step at a time to the run furthest behind, so that the
    /// runs stay together when `budget` (wall seconds) ends the call first.
    /// @param t       the simulated time to reach, s
    /// @param budget  wall time allowed for the call, s
    /// @param before  called before each step of a run (e.g. to hold a dragged particle); may be empty
    /// @throws NotImplemented when a run hits a stub (its message keeps the text)
    void advanceTo(double t, double budget = std::numeric_limits<double>::infinity(),
                   const std::function<void(CompareRun&)>& before = {});
    /// Steps run i once (the app's Step button), with the same checks.
    /// @param i  the run
    void stepRun(size_t i);
    /// Appends a sample (CompareSample) to every run with a simulation (to a stopped one once, where it stopped).
    void sample();
    /// The lowest simulated time of the runs that can go on (the common time; else the highest), s.
    double time() const;
    /// The error measure (compareMeasure() of the first run with a simulation; "energy_drift" [J] when none has one).
    const CompareMeasure& measure() const { return measure_; }
    /// The runs.
    std::vector<CompareRun>& runs() { return runs_; }
    /// The runs.
    const std::vector<CompareRun>& runs() const { return runs_; }

private:
    void step(CompareRun& r);
    std::vector<CompareRun> runs_;
    CompareMeasure measure_{"energy_drift", "J"};
};

/// Writes compare.csv: a header `method,t [s],wall [s],<measure> [<unit>],energy [J],max_strain [1]`
/// and one row per run per sample, in the order of the samples (17 significant digits; NaN as `nan`).
/// @param path  the file
/// @param c     the comparison
/// @throws InputError if the file cannot be written
void writeCompareCsv(const std::string& path, const Comparison& c);

/// Draws compare.png with gnuplot: the error measure against the wall time per simulated second
/// (log-log, one line per run, a point per sample), and against simulated time (log), the energy (its
/// axis spanning the runs that did not stop, when one did) and the max strain (when the scene has edges).
/// The data go to compare.dat, one block per run (gnuplot's `index`).
/// @param dir    folder; compare.dat, compare.gp and compare.png are written there
/// @param c      the comparison (labels, measure)
/// @param title  the figure's title, e.g. the scene file
/// @return       the PNG written, or "" (gnuplot missing or failed: a note on stderr)
std::string plotCompare(const std::string& dir, const Comparison& c, const std::string& title);

}  // namespace clothlab
