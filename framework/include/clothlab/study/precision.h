/// @file precision.h
/// @brief `clothlab study precision`: error against run time (work-precision) and convergence order.
///
/// Force-based methods sweep the time step Δt. Position-based methods ("pbd", "xpbd") keep the
/// scene's frame step Δt and sweep the solver budget instead: `iterations` = b with one substep, or
/// `substeps` = b with one iteration, for every b in PrecisionOptions::budgets. Their cost axis is the
/// number of constraint projections per simulated second, (number of constraints) · iterations · substeps / Δt,
/// so a run with b iterations and a run with b substeps cost the same number of projections.
#pragma once
#include <functional>
#include <limits>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "clothlab/core/scene.h"
#include "clothlab/core/types.h"

namespace clothlab {

/// Settings of a work-precision study.
struct PrecisionOptions {
    /// Methods to compare, one line each (any solver.method makeSimulation() accepts, e.g. later "pbd").
    std::vector<Method> methods = {Method::ExplicitEuler, Method::SymplecticEuler, Method::VelocityVerlet, Method::Rk4,
                                   Method::ImplicitEuler};
    double dt_min = 1e-4;       ///< smallest time step, s
    double dt_max = 1e-2;       ///< largest time step, s
    int dt_count = 7;           ///< time steps, log-spaced; each is rounded so that end_time / dt is a whole number
    double end_time = 1.0;      ///< simulated time T at which the error is measured, s
    Method reference_method = Method::Rk4;  ///< reference run when there is no analytic solution ("xpbd" for pbd/xpbd scenes)
    double reference_dt = 0.0;  ///< its time step, s (0: dt_min / 8)
    /// Position-based methods: the budgets b (iterations or substeps per frame) of the sweep.
    std::vector<int> budgets = {1, 2, 5, 10, 20, 50, 100};
    /// Position-based methods: which knobs to sweep, "iterations" and/or "substeps".
    std::vector<std::string> sweeps = {"iterations", "substeps"};
    /// Position-based reference: substeps per frame (each with reference_iterations iterations).
    int reference_substeps = 1000;
    /// Position-based reference: iterations per substep.
    int reference_iterations = 1;
    /// Runs shorter than 0.2 s are timed up to this many times (their best wall time counts); the
    /// errors do not change, so a study that needs only them (a graded test) passes 1.
    int repeats = 5;
    /// Called after each run with (runs done, runs in total, the run's label); may be empty.
    std::function<void(int, int, const std::string&)> progress;
};

/// One run of the study.
struct PrecisionRun {
    Method method = Method::SymplecticEuler;  ///< solver.method
    double dt = 0.0;        ///< time step, s
    long long steps = 0;    ///< steps to reach end_time
    double error = 0.0;     ///< RMS over particles of |x_i(T) − x_i^ref(T)|, m (NaN if unstable)
    double wall = 0.0;      ///< wall time of the steps, s (short runs: the best of up to PrecisionOptions::repeats)
    bool unstable = false;  ///< the run blew up (no error value)
    std::string series;     ///< the line it belongs to: the method, or "<method> iterations|substeps" (position-based)
    int iterations = 0;     ///< position-based: iterations per substep (0 for force-based runs)
    int substeps = 0;       ///< position-based: substeps per frame (0 for force-based runs)
    double projections = 0.0;  ///< position-based: constraint projections per simulated second, 1/s
    double strain = std::numeric_limits<double>::quiet_NaN();  ///< RMS edge strain at T (metric rms_strain), 1; NaN if the model has none
};

/// A whole study.
struct PrecisionResult {
    std::string scene;              ///< scene file
    std::string reference;          ///< "analytic" or "<method> at dt = ..."
    double end_time = 0.0;          ///< T, s
    std::vector<PrecisionRun> runs; ///< every run
    /// Per series: the measured order (force-based: slope of log error over log Δt) or, for a
    /// position-based series, the slope of log error over log projections per second (NaN if fewer than 2 usable runs).
    std::map<std::string, double> slopes;
    double reference_change = 0.0;  ///< position-based: RMS |x_ref − x_ref(half the substeps)|, m: the size of the reference's own error
    double reference_strain = std::numeric_limits<double>::quiet_NaN();  ///< RMS edge strain of the reference at T
    bool position_based = false;    ///< some run is position-based (cost axis = projections per second)
};


/// The scene of one position-based run: `method` with `iterations` per substep and `substeps` per
/// frame at the scene's frame step Δt. PBD's stiffnesses k ∈ [0, 1] and the damping k_damping act once
/// per (sub)step, so they are converted to the k_sub of exercise 3.2 (iterationStiffness(k, substeps)),
/// for which (1 − k_sub)^substeps = 1 − k: the same effect per frame, and every configuration simulates the same cloth (k = 1 stays 1;
/// XPBD's compliances α are material constants and stay).
/// @param scene       the base scene (model "cloth")
/// @param method      Method::Pbd or Method::Xpbd
/// @param iterations  iterations per substep, >= 1
/// @param substeps    substeps per frame, >= 1
Scene positionBasedScene(const Scene& scene, Method method, int iterations, int substeps);

/// The reference positions at time T: the analytic solution for the single-spring scene when it has
/// one (singleSpringAnalytic()), else a run of `reference_method` at `reference_dt`; for a
/// position-based reference method, `reference_method` with `reference_substeps` substeps of
/// `reference_iterations` iterations per frame (positionBasedScene()).
/// @param scene     the scene
/// @param options   end time and reference settings
/// @param label     set to "analytic" or "<method> at dt = <dt> s"
/// @return          reference positions at T, 3 x N, m
Matrix3X precisionReference(const Scene& scene, const PrecisionOptions& options, std::string* label);

/// Runs every method at every Δt to the end time and measures error and wall time.
/// @param scene    the base scene
/// @param options  methods, Δt grid, end time, reference, progress callback
PrecisionResult precisionStudy(const Scene& scene, const PrecisionOptions& options);

/// The convergence order of one method: the least-squares slope of log(error) over log(Δt) of its
/// stable runs with error above 10⁻¹³ m (the round-off floor); NaN if fewer than two such runs.
/// Error ≈ C Δt^p gives slope p: 1 for explicit and symplectic Euler and implicit Euler, 2 for Verlet, 4 for RK4.
/// @param runs    the runs (other methods are ignored)
/// @param method  the method
double convergenceSlope(const std::vector<PrecisionRun>& runs, const std::string& method);

/// The work-precision slope of one position-based series: the least-squares slope of log(error) over
/// log(projections per second) of its stable runs with error above 10⁻¹³ m; NaN if fewer than two.
/// Slope −1: ten times the cost buys ten times less error; 0: more cost buys nothing.
/// @param runs    the runs (other series are ignored)
/// @param series  the series, e.g. "pbd substeps"
double costSlope(const std::vector<PrecisionRun>& runs, const std::string& series);

/// Writes the runs as CSV: `method,dt [s],steps,error [m],wall [s],unstable,series,iterations,substeps,projections_per_s [1/s],rms_strain [1]`.
/// @throws InputError if the file cannot be written
void writePrecisionCsv(const std::string& path, const PrecisionResult& result);

/// Prints the table (method, Δt, steps, error, wall time) and the measured order per method.
void printPrecisionTable(std::ostream& out, const PrecisionResult& result);

/// Writes `precision.png` (error against wall time, log-log, one line per method: the work-precision
/// diagram) and `convergence.png` (error against Δt with the measured slopes) with gnuplot. With
/// position-based runs: `precision.png` has two panels, position error and RMS edge strain against
/// constraint projections per simulated second, one line per series, and `precision_wall.png` shows
/// the position error against wall time.
/// @param dir     output folder (holds the CSV already)
/// @param result  the study
/// @return        the PNG files written (empty if gnuplot is missing or failed; a note goes to stderr)
std::vector<std::string> plotPrecision(const std::string& dir, const PrecisionResult& result);

}  // namespace clothlab
