/// @file stability.h
/// @brief `clothlab study stability`: sweep stiffness k and time step Δt, classify each run stable or not.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "clothlab/core/scene.h"

namespace clothlab {

/// When a run counts as unstable.
struct StabilityCriteria {
    long long steps = 1000;       ///< steps per run
    double energy_factor = 100.0; ///< unstable if E(t) − E(0) > energy_factor · E_scale (see classifyStability())
};

/// The verdict on one run.
struct StabilityVerdict {
    bool stable = true;          ///< no NaN/Inf, stayed in bounds, energy did not grow beyond the factor
    long long steps = 0;         ///< steps done before the verdict
    double energy_growth = 0.0;  ///< largest (E(t) − E(0)) / E_scale seen
    std::string reason;          ///< why unstable ("" when stable)
};

/// Runs the scene for criteria.steps steps and classifies it. Unstable when the state turns NaN or
/// Inf, a particle leaves the ball of radius \f$ 10^3 (L + 1\,\mathrm{m}) \f$ (L: extent of the initial
/// positions), or the total energy rises by more than energy_factor · E_scale with
/// \f$ E_{scale} = \max(|E(0)|,\ m_{gesamt}\,|g|\,L,\ 10^{-12}\,\mathrm{J}) \f$ (checked every
/// steps/100 steps; a blow-up grows exponentially, so it cannot hide between checks).
/// A simulation without an "energy" metric is judged by NaN/Inf and bounds only.
/// @param scene     the scene (its solver.method and solver.dt are used)
/// @param criteria  steps and energy factor
StabilityVerdict classifyStability(const Scene& scene, const StabilityCriteria& criteria);

/// Settings of a stability sweep.
struct StabilityOptions {
    /// Methods to sweep (any solver.method makeSimulation() accepts).
    std::vector<Method> methods = {Method::ExplicitEuler, Method::SymplecticEuler, Method::VelocityVerlet, Method::Rk4,
                                   Method::ImplicitEuler};
    double k_min = 1.0;      ///< smallest (structural) stiffness, N/m
    double k_max = 1e6;      ///< largest stiffness, N/m
    int k_count = 13;        ///< stiffness values, log-spaced
    double dt_min = 1e-5;    ///< smallest time step, s
    double dt_max = 1e-1;    ///< largest time step, s
    int dt_count = 13;       ///< time steps, log-spaced
    StabilityCriteria criteria;  ///< what counts as unstable
    /// Called after each run with (runs done, runs in total, the run's method); may be empty.
    std::function<void(int, int, const std::string&)> progress;
};

/// One point of the stability map.
struct StabilityPoint {
    Method method = Method::SymplecticEuler;  ///< solver.method
    double k = 0.0;            ///< stiffness, N/m
    double dt = 0.0;           ///< time step, s
    double omega_max = 0.0;    ///< ω_max at this k, rad/s
    StabilityVerdict verdict;  ///< the measured outcome
};

/// A whole stability sweep.
struct StabilityResult {
    std::string scene;                  ///< scene file
    Model model = Model::Spring;        ///< spring, chain or cloth
    double k_ref = 0.0;                 ///< the scene's own stiffness, N/m
    double omega_ref = 0.0;             ///< ω_max at k_ref, rad/s (ω_max(k) = ω_ref √(k / k_ref))
    double min_mass = 0.0;              ///< smallest free particle mass, kg (for Provot's k_krit)
    std::vector<StabilityPoint> points; ///< every (method, k, dt) run
};

/// `count` values from lo to hi, evenly spaced in log scale (lo, ..., hi; one value: lo).
std::vector<double> logSpace(double lo, double hi, int count);

/// Sweeps methods × k × Δt (log grids) and classifies every run.
/// @param scene    the base scene; its k is replaced by withStiffness(), its dt by the grid
/// @param options  grid, methods, criteria, progress callback
StabilityResult stabilitySweep(const Scene& scene, const StabilityOptions& options);

/// The measured critical time step of one method at the scene's own stiffness: bisection (in log Δt)
/// between a stable dt_lo and an unstable dt_hi until they differ by less than a factor 1 + rel_tol.
/// @param scene     the scene
/// @param method    solver.method to use
/// @param dt_lo     a stable time step, s
/// @param dt_hi     an unstable time step, s
/// @param criteria  what counts as unstable
/// @param rel_tol   relative width of the final bracket
/// @return          the geometric mean of the final bracket, s; −1 if dt_lo is unstable, +∞ if dt_hi is stable
double measureCriticalDt(const Scene& scene, Method method, double dt_lo, double dt_hi,
                         const StabilityCriteria& criteria, double rel_tol = 0.01);

/// Writes the sweep as CSV: `method,k [N/m],dt [s],omega_max_dt [1],stable,steps,energy_growth [E_scale],reason`.
/// @throws InputError if the file cannot be written
void writeStabilityCsv(const std::string& path, const StabilityResult& result);

/// Prints, per method, a text map (rows Δt, columns k; '#' unstable, '.' stable) and the theory.
void printStabilityTable(std::ostream& out, const StabilityResult& result);

/// Writes the stability maps as PNGs with gnuplot: `stability_<method>.png` per method and
/// `stability.png` with all methods side by side, each with the theoretical bounds
/// ω_max Δt = 2 (symplectic Euler, Verlet), ω_max Δt = 2√2 (RK4) and Provot's Δt = π/ω_max drawn in.
/// @param dir     output folder (holds the CSV already)
/// @param result  the sweep
/// @return        the PNG files written (empty if gnuplot is missing or failed; a note goes to stderr)
std::vector<std::string> plotStability(const std::string& dir, const StabilityResult& result);

/// One run of the collision map.
struct CollisionPoint {
    double dt = 0.0;          ///< time step, s
    int iterations = 0;       ///< solver iterations
    bool stays = true;        ///< no particle fell through a collider and the run did not stop
    bool unstable = false;    ///< the run stopped (run.h: StopCause)
    long long step = 0;       ///< the step it fell through or stopped (0: stays)
    std::string message;      ///< the warning or stop message ("" when it stays)
};

/// The collision axis of the stability study: Δt × iterations, stays on the collider or not.
struct CollisionResult {
    std::string scene;                   ///< scene file
    double dt_ref = 0.0;                 ///< the scene's own Δt, s
    int iterations_ref = 0;              ///< the scene's own iterations
    double seconds = 0.0;                ///< simulated time of every run, s
    std::vector<CollisionPoint> points;  ///< every (Δt, iterations) run
};

/// Runs a scene with colliders for `seconds` of simulated time at every Δt × iterations and records
/// whether it stays on its colliders: the run checks of run.h (RunChecks) flag a particle that fell
/// through (WarningKind::FellThrough; the run ends there) or a stop.
/// @param scene       a position-based scene with colliders
/// @param dts         time steps, s
/// @param iterations  solver iterations
/// @param seconds     simulated time per run, s
/// @param progress    called after each run with (runs done, runs in total, ""); may be empty
/// @throws InputError if the scene has no colliders or is not position-based
CollisionResult collisionSweep(const Scene& scene, const std::vector<double>& dts, const std::vector<int>& iterations, double seconds,
                               const std::function<void(int, int, const std::string&)>& progress = {});

/// Writes the collision map as CSV: `dt [s],iterations,stays,unstable,step,message`.
/// @throws InputError if the file cannot be written
void writeCollisionCsv(const std::string& path, const CollisionResult& result);

/// Prints the collision map as text: rows Δt, columns iterations; '.' stays, 'F' fell through, '#' unstable.
void printCollisionTable(std::ostream& out, const CollisionResult& result);

/// Draws collision.png with gnuplot: Δt against iterations, stays / fell through / unstable, the
/// scene's own setting marked.
/// @param dir     output folder
/// @param result  the sweep
/// @return        the PNG written, or "" (gnuplot missing or failed; a note goes to stderr)
std::string plotCollision(const std::string& dir, const CollisionResult& result);

}  // namespace clothlab
