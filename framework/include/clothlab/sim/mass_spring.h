/// @file mass_spring.h
/// @brief Force-based simulation of a mass-spring system (Masse-Feder-System) with any integrator.
#pragma once
#include <functional>
#include <optional>

#include "clothlab/core/spring.h"
#include "clothlab/exercise/01_hooke.h"
#include "clothlab/sim/analytic.h"
#include "clothlab/sim/simulation.h"

namespace clothlab {

/// Particles and springs built from a scene's model.
struct MassSpringModel {
    State state;                  ///< initial particles
    std::vector<Spring> springs;  ///< all springs
};

/// The single spring: particle 0 is the pinned anchor, particle 1 hangs from it.
MassSpringModel makeSingleSpring(const SingleSpringSpec& spec);

/// A chain of n particles along `direction`, links of rest length l0, particle 0 pinned.
MassSpringModel makeChain(const ChainSpec& spec);

/// The 1-D analytic solution of the single-spring scene, when the motion stays on the
/// spring's line (start − anchor, initial velocity and gravity all parallel).
std::optional<DampedOscillator> singleSpringAnalytic(const Scene& scene);

/// Explicit time integration of a mass-spring model: force terms (gravity, damping,
/// springs, ...) summed into F(x, v), then one integrator step.
class MassSpringSimulation : public Simulation {
public:
    /// A force term: adds its forces into f.
    using ForceTerm = std::function<void(const Matrix3X& x, const Matrix3X& v, Matrix3X& f)>;

    /// @param scene  a scene with model spring or chain (cloth: see stage 02)
    /// @param model  its particles and springs
    MassSpringSimulation(const Scene& scene, MassSpringModel model);
    /// Adds a force pass named `name` (shown in the timing report).
    void addForce(const std::string& name, ForceTerm term);
    void step() override;
    std::vector<Metric> metrics() const override;
    /// Total energy: kinetic + gravity + springs, J.
    double energy() const;

protected:
    std::vector<Spring> springs_;          ///< the springs
    std::vector<std::pair<int, ForceTerm>> forces_;  ///< (pass id, term)
    int integrate_pass_ = -1;              ///< pass id of the integrator
    double initial_energy_ = 0.0;          ///< E at t = 0, J
    std::optional<DampedOscillator> analytic_;  ///< exact solution, when there is one
    Vec3 anchor_{0, 0, 0};                 ///< fixed end of the 1-D solution's line, m
    Vec3 axis_{0, -1, 0};                  ///< unit direction of that line
    mutable double max_error_ = 0.0;       ///< largest error against the analytic solution so far, m
};

}  // namespace clothlab
