/// @file extremes.h
/// @brief `clothlab study extremes`: the extreme matrix (stiffness, Δt, mass ratios, degenerate
/// geometry, PBD iterations, XPBD compliance) for every method that applies, each run classified
/// stable / reported (stopped or warned, with the step) / silently wrong.
#pragma once
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "clothlab/sim/run.h"

namespace clothlab {

/// The verdict on one run of the matrix.
enum class ExtremeOutcome {
    Stable,        ///< ran every step: finite, no warning
    Stopped,       ///< stopped with "unstable at step N" (run.h: StopCause)
    Warned,        ///< ran to the end with a warning (run.h: RunWarning) that says what is wrong, from which step
    SilentlyWrong  ///< NaN/Inf in the state or the report without a stop, a particle through a collider without
                   ///< FellThrough, or the energy above E(0) + 100 E_scale without a stop or warning
};

/// One case of the matrix: a model with an extreme or degenerate feature, built for (method, p, Δt).
struct ExtremeCase {
    std::string name;        ///< e.g. "chain, masses 1e-3 and 1e3 kg (ratio 1e6)"
    bool position_based;     ///< true: runs with pbd and xpbd; false: with the five force-based methods
    /// Builds the simulation. p is the method's axis (extremeAxis()): stiffness k (N/m) for a
    /// force-based method, iterations for pbd, distance and bending compliance for xpbd.
    std::function<std::unique_ptr<Simulation>(Method method, double p, double dt)> make;
};

/// Every case: force-based — one spring; chains with mass ratios 1, 1e3 and 1e6; zero-length springs
/// with every particle coincident; two coincident particles; a 4 x 4 cloth; a zero-width cloth
/// (zero-length springs). Position-based (a 5 x 5 cloth with distance and bending constraints,
/// dropped 0.3 m onto a ground plane) — flat dihedrals (the cloth as it starts); mass ratio 1e6;
/// zero-area triangles (zero width); every particle coincident; two coincident particles; folded in
/// half onto itself (dihedral angle π); all-pinned stencils (two rows pinned).
/// @param scenes_dir  the folder with the shipped scenes the cases start from (spring.json, chain.json,
///                    mfn_hanging.json, pbd_ground.json)
std::vector<ExtremeCase> extremeCases(const std::string& scenes_dir);

/// The name and unit of a method's axis: "k [N/m]", "iterations [1]" or "compliance [m/N]".
std::string extremeAxis(Method method);

/// One run of the matrix.
struct ExtremeCell {
    std::string case_name;   ///< ExtremeCase::name
    Method method = Method::SymplecticEuler;  ///< solver.method
    double p = 0.0;          ///< the method's axis value (extremeAxis())
    double dt = 0.0;         ///< time step, s
    ExtremeOutcome outcome = ExtremeOutcome::Stable;  ///< the verdict
    long long step = 0;      ///< Stopped: the step; Warned: the step the first warning started; else 0
    std::string message;     ///< the stop message, the first warning's headline, or what was silently wrong
};

/// Runs `steps` steps with runSimulation() (a report row every step) and classifies the run. The
/// silently-wrong checks are independent of run.h's: every report row's metrics finite; no free
/// particle that started outside a collider (d ≥ −h) ends a step at d < −max(4 h, 1 mm) unless a
/// FellThrough warning was given; the energy never above E(0) + 100 E_scale (energyScale()) unless
/// the run stopped or warned.
/// @param sim    the simulation, before its first step
/// @param steps  number of steps
ExtremeCell classifyExtremeRun(Simulation& sim, long long steps);

/// Settings of the matrix.
struct ExtremesOptions {
    std::vector<double> ks = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};  ///< stiffness, N/m
    std::vector<double> dts = {1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1};               ///< time steps, s
    std::vector<double> iterations = {1, 3, 10, 30, 100, 300, 1000};           ///< PBD solver iterations
    std::vector<double> compliances = {0, 1e-9, 1e-6, 1e-3, 1};                ///< XPBD compliance, m/N
    std::vector<Method> methods = allMethods();  ///< methods to run (each case runs those that apply)
    long long steps = 100;                       ///< steps per run
    /// Called after each run with (runs done, runs in total, the run's case); may be empty.
    std::function<void(int, int, const std::string&)> progress;
};

/// Runs every case with every method that applies over its axis × Δt.
/// @param cases    the cases (extremeCases())
/// @param options  grid, methods, steps, progress
std::vector<ExtremeCell> extremesStudy(const std::vector<ExtremeCase>& cases, const ExtremesOptions& options);

/// Writes the cells as CSV: `case,method,axis,p,dt [s],outcome,step,message`.
/// @throws InputError if the file cannot be written
void writeExtremesCsv(const std::string& path, const std::vector<ExtremeCell>& cells);

/// Writes the table as markdown: per case and method the map (rows Δt, columns the axis; '.' stable,
/// 'w' warned, 'u' stopped unstable, 'X' silently wrong) and the counts; then every silently wrong
/// cell. The same table is printed by `clothlab study extremes`.
/// @param out      the stream
/// @param cells    the cells
/// @param command  the command that made them (printed above the table)
void writeExtremesMarkdown(std::ostream& out, const std::vector<ExtremeCell>& cells, const std::string& command);

/// Draws extremes.png with gnuplot: one row per case and method, one square per cell, coloured by outcome.
/// @param dir    output folder
/// @param cells  the cells
/// @return       the PNG written, or "" (gnuplot missing or failed; a note goes to stderr)
std::string plotExtremes(const std::string& dir, const std::vector<ExtremeCell>& cells);

}  // namespace clothlab
