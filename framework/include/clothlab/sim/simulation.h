/// @file simulation.h
/// @brief A running simulation built from a scene: state, step, metrics and pass timings.
#pragma once
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "clothlab/core/scene.h"
#include "clothlab/core/state.h"
#include "clothlab/sim/pass_timer.h"
#include "clothlab/sim/strain.h"

namespace clothlab {

/// One named number of the run report (energy, error against the analytic solution, strain, ...).
struct Metric {
    std::string name;  ///< short name, e.g. "energy_drift"
    double value;      ///< its value
    std::string unit;  ///< its unit, e.g. "J", "m", "1" (dimensionless fraction), "rad"
};

/// A step the method could not take, e.g. implicit Euler's linear solve did not converge.
/// Thrown by Simulation::step(); the state is then left as it was before the step.
struct SolverFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Base of every method. A subclass assembles only the passes its scene uses.
///
/// The report's measures are defined once, here, for every method:
/// - `energy` = kinetic + gravitational + elastic energy (J), `energy_drift` = energy − energy at t = 0 (J);
/// - `max_strain`, `rms_strain` (1): edgeStrain() of the cloth's mesh edges (or the springs of a chain),
///   rest lengths from the initial shape;
/// then whatever the method adds (error against the analytic solution, bending error, penetration).
class Simulation {
public:
    /// @param scene  the validated scene (copied)
    explicit Simulation(const Scene& scene) : scene_(scene) {}
    virtual ~Simulation() = default;

    /// Advances the state by one time step Δt = scene().solver.dt.
    /// @throws SolverFailure when the method cannot take the step
    virtual void step() = 0;

    /// The report's metrics for the current state (see the class comment).
    std::vector<Metric> metrics() const;
    /// Kinetic + gravitational + elastic energy, J.
    double energy() const;
    /// Strain of the measured edges (cloth: mesh edges; chain and spring: the springs).
    EdgeStrain strain() const;

    /// Current particle state.
    virtual const State& state() const = 0;
    /// Current particle state, writable (e.g. for dragging a particle in the app).
    virtual State& state() = 0;
    /// Wall time per pass so far.
    const PassTimer& timer() const { return timer_; }
    /// The scene this simulation was built from.
    const Scene& scene() const { return scene_; }
    /// The pass that first moved a pinned particle (w = 0) inside a step, e.g. "constraints: distance";
    /// "" when none did or the method does not check its passes (RunChecks then names the whole step).
    const std::string& pinMovedBy() const { return pinMovedBy_; }
    /// The pass that first created linear momentum beyond round-off (checkMomentum()), "" when none did.
    const std::string& momentumCreatedBy() const { return momentumBy_; }
    /// What it created: \f$ |\sum_i m_i \Delta\vec p_i| / \sum_i m_i |\Delta\vec p_i| \f$ over that pass (1; 0 when none).
    double momentumCreated() const { return momentumCreated_; }
    /// Which pass blew the state up: the step from `before` is taken again with a check after each
    /// pass, and the first pass after which a position is NaN or infinite or a particle left the
    /// region \f$ |\vec x_i| < \f$ `bound` is named, e.g. "constraints: distance"; "" when the method
    /// checks no passes (only position-based methods do) or none did. The state is left as the step
    /// left it. For the message of a blow-up (stepAndCheck()), never on the hot path.
    /// @param before  the state before the step that blew up
    /// @param bound   the region's radius, m (report.blowup)
    std::string blowUpBy(const State& before, double bound);
    /// Edges to draw (springs or distance constraints), pairs of particle indices.
    const std::vector<Eigen::Vector2i>& edges() const { return edges_; }
    /// Triangles to draw (cloth surface), triples of particle indices; empty for springs and chains.
    const std::vector<Eigen::Vector3i>& triangles() const { return triangles_; }

protected:
    /// Call at the end of a subclass constructor, once state(), edges_ and triangles_ are set:
    /// takes the rest lengths of the strain edges and the initial energy from the initial state.
    void initMeasures();
    /// After pass `pass` (a timer_ id) changed the predicted positions p (3 x N, m): a pinned particle
    /// (w_i = 0) keeps \f$ p_i = x_i \f$; the first pass that breaks this is remembered (pinMovedBy()).
    /// @param p     the predicted positions after the pass, m
    /// @param pass  the pass, as timer_.add() returned it
    void checkPins(const Matrix3X& p, int pass);
    /// After pass `pass` of constraints between particles (no collider) moved the predicted positions
    /// from `before` to `p`, in a scene without pinned particles: the pass keeps the linear momentum,
    /// \f$ |\sum_i m_i (\vec p_i - \vec p_i^{before})| \le 10^{-6} \sum_i m_i |\vec p_i - \vec p_i^{before}| \f$
    /// (and above round-off, \f$ 10^{-12} \sum_i m_i |\vec p_i| \f$); the first pass that breaks this is
    /// remembered (momentumCreatedBy()). With pins the check is off (a pin is an infinite mass).
    /// @param before  the predicted positions before the pass, m
    /// @param p       after it, m
    /// @param pass    the pass, as timer_.add() returned it
    void checkMomentum(const Matrix3X& before, const Matrix3X& p, int pass);
    /// Only inside blowUpBy(): after pass `pass` changed the positions or velocities `q` (3 x N), the
    /// first pass that left one of them NaN or infinite, or with a norm of at least the bound, is
    /// remembered. Costs nothing otherwise.
    /// @param q     positions (m) or velocities (m/s) after the pass
    /// @param pass  the pass, as timer_.add() returned it
    void checkBlowUp(const Matrix3X& q, int pass) {
        if (blowUpBound_ > 0.0 && blowUpBy_.empty()) noteBlowUp(q, pass);
    }
    /// The scene has pinned particles (w = 0): checkMomentum() does nothing then.
    bool hasPins() const { return !pinned_.empty(); }
    /// Elastic energy of the method's springs (0 for position-based methods), J.
    virtual double elasticEnergy() const { return 0.0; }
    /// Appends the method's own metrics after the common ones.
    virtual void addMetrics(std::vector<Metric>& m) const { (void)m; }

    Scene scene_;                               ///< the scene
    PassTimer timer_;                           ///< pass timings
    std::vector<Eigen::Vector2i> edges_;        ///< for display
    std::vector<Eigen::Vector3i> triangles_;    ///< for display

private:
    std::vector<Eigen::Vector2i> strainEdges_;  ///< edges whose strain is reported
    std::vector<double> strainRest_;            ///< their rest lengths, m
    double initialEnergy_ = 0.0;                ///< energy at t = 0, J
    std::vector<int> pinned_;                   ///< the particles with w = 0
    std::string pinMovedBy_;                    ///< see pinMovedBy()
    std::string blowUpBy_;                      ///< see blowUpBy()
    double blowUpBound_ = 0.0;                  ///< > 0 only inside blowUpBy(): checkBlowUp() checks
    void noteBlowUp(const Matrix3X& q, int pass);
    std::string momentumBy_;                    ///< see momentumCreatedBy()
    double momentumCreated_ = 0.0;              ///< see momentumCreated()
};

/// Builds the simulation for a scene's model and solver.method.
/// @throws InputError when the combination is not supported
std::unique_ptr<Simulation> makeSimulation(const Scene& scene);

}  // namespace clothlab
