/// @file precision.h
/// @brief `clothlab study precision`: error against run time (work-precision) and convergence order.
#pragma once
#include <functional>
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
    std::vector<std::string> methods = {"explicit_euler", "symplectic_euler", "velocity_verlet", "rk4", "implicit_euler"};
    double dt_min = 1e-4;       ///< smallest time step, s
    double dt_max = 1e-2;       ///< largest time step, s
    int dt_count = 7;           ///< time steps, log-spaced; each is rounded so that end_time / dt is a whole number
    double end_time = 1.0;      ///< simulated time T at which the error is measured, s
    std::string reference_method = "rk4";  ///< reference run when there is no analytic solution
    double reference_dt = 0.0;  ///< its time step, s (0: dt_min / 8)
    /// Called after each run with (runs done, runs in total, the run's method); may be empty.
    std::function<void(int, int, const std::string&)> progress;
};

/// One run of the study.
struct PrecisionRun {
    std::string method;     ///< solver.method
    double dt = 0.0;        ///< time step, s
    long long steps = 0;    ///< steps to reach end_time
    double error = 0.0;     ///< RMS over particles of |x_i(T) − x_i^ref(T)|, m (NaN if unstable)
    double wall = 0.0;      ///< wall time of the steps, s (short runs: the best of up to 5 repeats)
    bool unstable = false;  ///< the run blew up (no error value)
};

/// A whole study.
struct PrecisionResult {
    std::string scene;              ///< scene file
    std::string reference;          ///< "analytic" or "<method> at dt = ..."
    double end_time = 0.0;          ///< T, s
    std::vector<PrecisionRun> runs; ///< every run
    std::map<std::string, double> slopes;  ///< measured order per method (NaN if fewer than 2 usable runs)
};

/// The reference positions at time T: the analytic solution for the single-spring scene when it has
/// one (singleSpringAnalytic()), else a run of `reference_method` at `reference_dt`.
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

/// Writes the runs as CSV: `method,dt,steps,error,wall,unstable`.
/// @throws InputError if the file cannot be written
void writePrecisionCsv(const std::string& path, const PrecisionResult& result);

/// Prints the table (method, Δt, steps, error, wall time) and the measured order per method.
void printPrecisionTable(std::ostream& out, const PrecisionResult& result);

/// Writes `precision.png` (error against wall time, log-log, one line per method: the work-precision
/// diagram) and `convergence.png` (error against Δt with the measured slopes) with gnuplot.
/// @param dir     output folder (holds the CSV already)
/// @param result  the study
/// @return        the PNG files written (empty if gnuplot is missing or failed; a note goes to stderr)
std::vector<std::string> plotPrecision(const std::string& dir, const PrecisionResult& result);

}  // namespace clothlab
