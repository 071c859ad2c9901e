/// @file sag.h
/// @brief `clothlab study sag`: the static sag of a hanging cloth against the solver iterations,
/// PBD against XPBD (chapter 10 of the slides).
///
/// The sag of a run is how far the lowest particle has dropped below the lowest particle of the
/// start, after `seconds` of simulated time:
/// \f[ s = \min_i y_i(0) - \min_i y_i(T) \qquad [\mathrm{m}] \f]
/// For a hanging cloth that has come to rest this measures how much the cloth stretches under its own
/// weight. PBD (stiffness k ∈ [0, 1]) gets stiffer with every extra iteration, because only the
/// unconverged Gauss–Seidel sweeps make it soft: its sag falls towards 0 as the iterations grow. XPBD
/// (compliance α, m/N) converges to the sag of a material with stiffness 1/α: the same sag for every
/// iteration count once the solve has converged.
#pragma once
#include <ostream>
#include <string>
#include <vector>

namespace clothlab {

/// Settings of a sag study.
struct SagOptions {
    std::vector<int> iterations = {1, 2, 5, 10, 20, 50, 100};  ///< solver iterations to sweep
    double compliance = 0.01;         ///< XPBD compliance α of the distance constraints, m/N
    std::vector<int> xpbd_substeps = {1, 10};  ///< one XPBD series per substep count
    double seconds = 3.0;             ///< simulated time T before the sag is measured, s
};

/// One series of the study: a label and the sag for each entry of SagOptions::iterations.
struct SagSeries {
    std::string label;        ///< e.g. "PBD, k = 1" or "XPBD, alpha = 0.01 m/N, 10 substeps"
    std::vector<double> sag;  ///< sag per iteration count, m (NaN if the run blew up)
};

/// The whole study.
struct SagResult {
    std::string scene;               ///< scene file and overrides (for the table)
    std::string file;                ///< scene file (for the plot's title)
    std::vector<int> iterations;     ///< the swept iteration counts
    std::vector<SagSeries> series;   ///< PBD first, then one XPBD series per substep count
    double seconds = 0.0;            ///< T, s
};

/// Runs the scene `scene_file` (with `overrides`, as `--set`) once per series and iteration count:
/// PBD with the scene's distance stiffness, then XPBD with `compliance` per entry of `xpbd_substeps`.
/// @param scene_file  a pbd/xpbd scene with a hanging cloth, e.g. scenes/pbd_curtain.json
/// @param overrides   scene overrides ("key=value")
/// @param o           what to sweep
SagResult sagStudy(const std::string& scene_file, const std::vector<std::string>& overrides, const SagOptions& o);

/// Prints the result as a table: one row per iteration count, one column per series, sag in mm.
void printSagTable(std::ostream& out, const SagResult& r);

/// Writes sag.csv (iterations, then one column per series, m) and draws sag.png with gnuplot
/// (sag against iterations, both axes logarithmic) into `dir`.
/// @return the files written
std::vector<std::string> writeSag(const std::string& dir, const SagResult& r);

}  // namespace clothlab
