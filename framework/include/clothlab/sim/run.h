/// @file run.h
/// @brief Running a simulation for a number of steps: why a run stopped, when its result is not a
/// result (warnings), and the report rows. The one place every program (run, render, app, studies)
/// takes its messages from.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "clothlab/sim/simulation.h"

namespace clothlab {

/// One row of the report time series.
struct ReportRow {
    long long step;               ///< steps done
    double t;                     ///< simulated time, s
    double wall;                  ///< wall time since the start, s
    std::vector<Metric> metrics;  ///< the scene's metrics at this time
};

/// Why a run stopped before its last step (one message per cause: stopReason()).
enum class StopCause {
    None,               ///< it did not stop
    PositionNotFinite,  ///< a position is NaN or infinite
    VelocityNotFinite,  ///< a velocity is NaN or infinite
    LeftRegion,         ///< a particle left the ball |x| < report.blowup (finite, but blown up)
    SolverFailure,      ///< the method could not take the step (SolverFailure, e.g. implicit Euler's solve)
    Strict              ///< with --strict (RunChecks strict): the first warning stops the run
};

/// What makes a finished run's numbers no result (RunChecks; `clothlab run --strict`: exit 3).
/// In the order of severity, the order of RunResult::warnings.
enum class WarningKind {
    PinMoved,      ///< a pinned particle (w = 0, infinite mass) moved: some pass ignored its inverse mass
    MomentumCreated,  ///< a pass of constraints between particles changed the linear momentum (no pins in the scene)
    FellThrough,   ///< a particle's path in one step reached kFellThroughFactor · h inside a collider
    NotConverged,  ///< RMS edge strain above kNotConvergedRmsStrain for a cloth meant to be inextensible
    Penetration,   ///< a particle more than (kPenetrationFactor − 1) h inside a collider at the end of a step
    EnergyGrowth   ///< the energy rose above E(0) by more than kEnergyGrowthBound · E_scale; for the
                   ///< symplectic methods only if its envelope kept rising or it passed kEnergyOscillationCap
                   ///< (growth, not a bounded oscillation: RunChecks)
};

/// RMS edge strain (1) above which a cloth meant to be inextensible (distance constraints with PBD
/// stiffness 1 or XPBD compliance 0) is "not converged": woven fabric stretches by a few per cent
/// under its own weight; 10 % RMS means the constraint solve has not caught up.
constexpr double kNotConvergedRmsStrain = 0.10;
/// Simulated time the RMS strain must stay above its bound before NotConverged fires (a transient
/// of an impact is no verdict), s; a run that ends above the bound fires as well.
constexpr double kNotConvergedDuration = 0.1;
/// Penetration warning: at the end of a step a particle is inside a collider, d < −(factor − 1) h,
/// i.e. its penetration h − d exceeds factor · h (thickness h = solver.thickness). PBD projects the
/// distance constraints after the collisions in every iteration, so a resting particle may end up to
/// about h inside the surface; twice that is no longer contact.
constexpr double kPenetrationFactor = 3.0;
/// Fell-through depth D = max(factor · h, kFellThroughMinDepth): see WarningKind::FellThrough.
constexpr double kFellThroughFactor = 4.0;
/// The smallest fell-through depth D (for h = 0), m.
constexpr double kFellThroughMinDepth = 1e-3;
/// EnergyGrowth bound, in units of energyScale(); scenes with wind (energy input) or pins moved
/// away from the rest shape (`"to"`: stored energy the constraints release) are not checked.
constexpr double kEnergyGrowthBound = 0.1;
/// Growth against oscillation: the envelope of g = (E − E0)/E_scale, its maximum over the steps
/// (s/2, s], must exceed (1 + kEnvelopeRise) times its maximum over [1, s/2] (taken as ≥ 0) at a
/// checkpoint s = 2^k for EnergyGrowth. A bounded oscillation (symplectic Euler, velocity Verlet: the
/// energy error oscillates about a modified energy, with the period of the fastest mode, π/(ω Δt)
/// steps or less for an error above the bound) has the same maximum in both windows.
constexpr double kEnvelopeRise = 0.1;
/// The first checkpoint that gives a verdict, in steps: each window then spans 32 steps or more, the
/// longest period of an energy oscillation that can exceed kEnergyGrowthBound (ω Δt > 0.2). A run
/// that ends earlier compares its last steps with the ones before them.
constexpr long long kEnergyFirstVerdict = 64;
/// The envelope rule is for the symplectic methods (symplectic_euler, velocity_verlet), whose energy
/// oscillates about a modified energy; for every other method a rise above kEnergyGrowthBound is
/// EnergyGrowth at once. A rise above this many E_scale is EnergyGrowth for every method: a band that
/// wide (ω Δt within 10 % of 2) is no result, however bounded.
constexpr double kEnergyOscillationCap = 10.0;

/// One warning of a run: what, where it started, how bad.
struct RunWarning {
    WarningKind kind = WarningKind::NotConverged;  ///< what
    long long step = 0;      ///< the step where it started (1 = the first step)
    double t = 0.0;          ///< the simulated time at the end of that step, s
    int collider = -1;       ///< Penetration, FellThrough: index into scene.colliders
    int particle = -1;       ///< Penetration, FellThrough, PinMoved: the first particle
    int count = 0;           ///< Penetration, FellThrough, PinMoved: particles affected so far
    std::string pass;        ///< PinMoved: the pass that moved it (Simulation::pinMovedBy()), or "" when not known;
                             ///< MomentumCreated: the pass (Simulation::momentumCreatedBy())
    double value = 0.0;      ///< NotConverged: RMS strain (1) at the end; Penetration: deepest h − d (m);
                             ///< FellThrough: deepest −d on a path (m); EnergyGrowth: largest (E − E0)/E_scale;
                             ///< PinMoved: how far the first particle moved (m); MomentumCreated: Simulation::momentumCreated() (1)
    double extra = 0.0;      ///< NotConverged: the max strain (1) at the end; else 0
};

/// The name of a stop cause as in summary.json, e.g. "left_region", "position_not_finite".
const char* causeName(StopCause c);
/// The name of a warning kind as in summary.json, e.g. "fell_through", "not_converged".
const char* warningName(WarningKind k);

/// The sentence for a warning: what happened, since which step, what would help. The one text the
/// CLI summary, summary.json, the renderer and the app show.
/// @param w      the warning
/// @param scene  the scene it came from (collider types, thickness, the settings to change)
std::string warningText(const RunWarning& w, const Scene& scene);

/// The warning in one short line, e.g. "fell through collider 0 (sphere) at step 18 (t = 0.54 s)"
/// (the app's status line; warningText() is the whole sentence).
/// @param w      the warning
/// @param scene  the scene it came from
std::string warningHeadline(const RunWarning& w, const Scene& scene);

/// Why a state can no longer be trusted: NaN/Inf position, NaN/Inf velocity, or a particle outside
/// the ball |x| < bound; StopCause::None when it can.
/// @param s      the state
/// @param bound  radius of the region the particles must stay in, m
StopCause instabilityCause(const State& s, double bound);

/// The one reason text of a stop cause, e.g. "a particle left the region |x| < 1e+06 m
/// (report.blowup); the state is finite but blown up". For SolverFailure: `detail` (the exception's text).
/// @param c       the cause (not None)
/// @param bound   the region's radius, m (LeftRegion)
/// @param detail  the solver's own message (SolverFailure)
std::string stopReason(StopCause c, double bound, const std::string& detail = "");

/// stopReason(instabilityCause(s, bound), bound), or "" when the state can be trusted.
/// @param s      the state
/// @param bound  radius of the region the particles must stay in, m
std::string instabilityReason(const State& s, double bound);

/// Takes one step and checks it: "" when the step went well, else the one message every program
/// prints, "unstable at step N (t = T s): <reason>", for a blow-up (instabilityReason()) or a step
/// the method could not take (SolverFailure).
/// @param sim    the simulation
/// @param step   the number of this step (1 for the first), for the message
/// @param bound  radius of the region the particles must stay in, m
/// @param cause  if not null, receives the cause (None when the step went well)
std::string stepAndCheck(Simulation& sim, long long step, double bound, StopCause* cause = nullptr);

/// stepAndCheck() with the scene's own bound, report.blowup.
/// @param sim   the simulation
/// @param step  the number of this step (1 for the first), for the message
inline std::string stepAndCheck(Simulation& sim, long long step) {
    return stepAndCheck(sim, step, sim.scene().report.blowup);
}

/// Energy scale of a simulation, J: \f$ E_{scale} = \max(|E(0)|,\ m_{free}\,|g|\,L,\ 10^{-12}\,\mathrm{J}) \f$
/// with the free mass m_free (kg) and the extent L of the current positions (m). Taken at t = 0.
/// @param sim  the simulation (its current state)
double energyScale(const Simulation& sim);

/// Lowest signed distance d (m) of a collider along the segment a → b, found by stepping with the
/// distance bound (colliderDistance() is 1-Lipschitz: within |d + depth| of a point nothing is
/// deeper than −depth); stops early once below −depth. Steps are at least max(0.25 depth, |b − a| / 64)
/// long (at most ~64 evaluations), so a path is missed only if it stays below −depth for less than that.
/// @param c      the collider
/// @param a      start of the path, m
/// @param b      end of the path, m
/// @param depth  the depth of interest D > 0, m
/// @param near   optional (speed only, the result is the same): a point of a mesh collider's surface
///               near a (MeshShape::closest(x, near)); becomes the closest point of the last point looked at
double pathDistance(const Collider& c, const Vec3& a, const Vec3& b, double depth, Vec3* near = nullptr);

/// A span of simulated time over which a run summarises every metric (`clothlab run --window T0,T1`):
/// a quantity that oscillates (the curtain's max strain swings with its sway) is measured over a
/// stated window, not at one moment.
struct MetricWindow {
    double from = 0.0;  ///< start t0, s
    double to = 0.0;    ///< end t1 ≥ t0, s
    /// Whether the state at time t (s) lies in [t0, t1]; a tolerance of 1e-9 s absorbs the rounding
    /// of t accumulated over the steps.
    /// @param t  simulated time, s
    bool contains(double t) const { return t >= from - 1e-9 && t <= to + 1e-9; }
};

/// One metric over a MetricWindow: over the states after every step (and the start) whose time t
/// lies in the window, \f$ \min_t m(t) \f$, the mean \f$ \frac{1}{N}\sum_t m(t) \f$ and \f$ \max_t m(t) \f$.
struct WindowStat {
    std::string name;   ///< the metric's name, e.g. "max_strain"
    std::string unit;   ///< its unit
    double min = 0.0;   ///< least value in the window
    double mean = 0.0;  ///< mean over the N states in the window
    double max = 0.0;   ///< largest value in the window
};

/// What runSimulation() did.
struct RunResult {
    long long steps = 0;          ///< steps done
    double wall = 0.0;            ///< wall time of the steps, s
    bool unstable = false;        ///< stopped because the state blew up or the solver failed
    StopCause cause = StopCause::None;  ///< why it stopped
    std::string message;          ///< "unstable at step N (t = ...): reason" when unstable
    std::vector<RunWarning> warnings;  ///< RunChecks::warnings() at the end, most severe kind first
    double worst_penetration = 0.0;    ///< RunChecks::worstPenetration(), m (0 without colliders)
    long long worst_penetration_step = 0;  ///< the step it was reached at
    std::vector<ReportRow> rows;  ///< one row every `every` steps and one at the end
    std::vector<std::string> notes;  ///< what a reader should know that does not make the run wrong, e.g. an
                                     ///< energy error above kEnergyGrowthBound that stays bounded (accuracy, not stability)
    bool windowed = false;           ///< a MetricWindow was given
    MetricWindow window;             ///< that window, s
    long long window_states = 0;     ///< the states N summarised in it (0: the run did not reach it)
    std::vector<WindowStat> window_stats;  ///< every metric over the window (empty when N = 0)
};

/// The checks of a run beside the step: the stop causes of stepAndCheck() and, without stopping,
/// the warnings (WarningKind) with the step where each started, and the worst penetration of the
/// whole run. One object per run; step() in place of sim.step().
///
/// Fell through: a free particle that was outside a collider, or within its thickness band
/// (d ≥ −h), at t = 0 and has not fallen through it yet, whose straight path x_old → x_new in one
/// step reaches d < −D, D = max(kFellThroughFactor h, kFellThroughMinDepth) (pathDistance()).
class RunChecks {
public:
    /// Takes the reference values from the simulation's current state: E(0), E_scale, which
    /// particles start outside which collider, where the pinned particles (w = 0) are.
    /// @param sim     the simulation, before its first step
    /// @param strict  the first warning stops the run (StopCause::Strict; `clothlab run --strict`)
    explicit RunChecks(const Simulation& sim, bool strict = false);

    /// One step of `sim` with every check: "" or the stop message of stepAndCheck() (with strict:
    /// or "stopped at step N (t = T s) by --strict: <the warning>").
    /// @param sim   the simulation given to the constructor
    /// @param step  the number of this step (1 for the first)
    std::string step(Simulation& sim, long long step);
    /// Ends the run: a NotConverged stretch still above the bound at the end fires now.
    /// @param sim  the simulation
    void finish(const Simulation& sim);
    /// Copies cause(), warnings() (most severe kind first), notes() and the worst penetration into `r`.
    /// @param r  the result of the run
    void collect(RunResult& r) const;

    /// Why the run stopped (None: it did not).
    StopCause cause() const { return cause_; }
    /// The warnings so far, in the order they fired.
    const std::vector<RunWarning>& warnings() const { return warnings_; }
    /// The notes so far (RunResult::notes): a bounded energy error above the bound, once the run ended.
    const std::vector<std::string>& notes() const { return notes_; }
    /// Largest penetration max(0, h − d) over every step end, particle and collider so far, m.
    double worstPenetration() const { return worstPenetration_; }

private:
    RunWarning& warn(WarningKind k, long long step, double t, int collider = -1);
    bool fired(WarningKind k) const;  ///< a warning of this kind fired already
    void checkColliders(const Simulation& sim, long long step);
    void checkStrain(const Simulation& sim, long long step);
    void checkEnergy(const Simulation& sim, long long step);
    void checkPins(const Simulation& sim, long long step);
    void judgeEnergy(double later, double before);

    Matrix3X xOld_;                        ///< positions before the step, m
    std::vector<Matrix3X> nearest_;        ///< per mesh collider: each particle's closest surface point at the last check (NaN: none; speeds up the search)
    std::vector<std::vector<char>> watch_; ///< per collider and particle: outside at t = 0, not fallen yet
    std::vector<std::vector<char>> penetrated_;  ///< per collider and particle: counted in the Penetration warning
    std::vector<RunWarning> warnings_;
    StopCause cause_ = StopCause::None;
    double e0_ = 0.0, eScale_ = 1.0;       ///< E(0) and energyScale(), J
    bool checkEnergy_ = true, checkStrain_ = false;
    std::string method_;                   ///< the scene's solver.method, for the advice
    bool oscillates_ = false;              ///< symplectic_euler or velocity_verlet: the envelope rule applies
    double gMax_ = 0.0;                    ///< largest g = (E − E0)/E_scale so far
    long long gAbove_ = 0;                 ///< first step with g > kEnergyGrowthBound (0: none)
    double gAboveT_ = 0.0;                 ///< its time, s
    double envBefore_ = -1e300, envWindow_ = -1e300;  ///< max g over [1, s/2] and over (s/2, now]
    double lastWindow_ = -1e300, lastBefore_ = -1e300;  ///< the two windows at the last checkpoint
    long long nextCheckpoint_ = 1;         ///< the next power of two
    std::vector<std::string> notes_;
    long long strainSince_ = 0;            ///< first step of the current stretch above the strain bound (0: none)
    double strainSinceT_ = 0.0;            ///< its time, s
    double worstPenetration_ = 0.0;
    long long worstPenetrationStep_ = 0;
    std::vector<int> pins_;                ///< the pinned particles (w = 0) at the start
    Matrix3X pinAt_;                       ///< their positions then, m (3 x pins)
    bool strict_ = false;
};

/// Steps `steps` times (or until the state turns NaN/Inf, leaves the ball of radius
/// scene.report.blowup or the solver fails) with RunChecks, recording a report row every `every` steps.
/// @param sim     the simulation
/// @param steps   number of steps
/// @param every   report interval in steps (≥ 1)
/// @param on_row  called with each row as it is recorded (progress output); may be empty
/// @param strict  the first warning stops the run (RunChecks)
/// @param window  if given, every metric is also summarised (WindowStat) over the states of every step
///                whose time lies in it, whatever `every` is
RunResult runSimulation(Simulation& sim, long long steps, long long every,
                        const std::function<void(const ReportRow&)>& on_row = {}, bool strict = false,
                        const MetricWindow* window = nullptr);

}  // namespace clothlab
