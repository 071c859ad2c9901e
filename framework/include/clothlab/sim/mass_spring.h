/// @file mass_spring.h
/// @brief Force-based simulation of a mass-spring system (Masse-Feder-System) with any integrator.
#pragma once
#include <functional>
#include <optional>

#include "clothlab/core/spring.h"
#include "clothlab/exercise/01_hooke.h"
#include "clothlab/sim/analytic.h"
#include "clothlab/sim/implicit_euler.h"
#include "clothlab/sim/rk4.h"
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

/// A cloth (stage 02): particles from makeGridState(), springs from makeClothSprings()
/// (structural, shear and bending as the scene's `springs` enable them).
MassSpringModel makeCloth(const Scene& scene);

/// The 1-D analytic solution of the single-spring scene, when the motion stays on the
/// spring's line (start − anchor, initial velocity and gravity all parallel).
std::optional<DampedOscillator> singleSpringAnalytic(const Scene& scene);

/// Time integration of a mass-spring model: force terms (gravity, damping, springs, ...)
/// summed into F(x, v), one integrator step (explicit_euler, symplectic_euler, velocity_verlet,
/// rk4 or implicit_euler), then, if the scene enables it, Provot's strain limit.
/// On a cloth the force terms are the stage-02 functions addClothSpringForces() and
/// addClothExternalForces(); on a spring or chain the framework's forces.h.
class MassSpringSimulation : public Simulation {
public:
    /// A force term: adds its forces into f.
    using ForceTerm = std::function<void(const Matrix3X& x, const Matrix3X& v, Matrix3X& f)>;

    /// @param scene  a scene with model spring, chain or cloth
    /// @param model  its particles and springs
    MassSpringSimulation(const Scene& scene, MassSpringModel model);
    /// Adds a force pass named `name` (shown in the timing report).
    void addForce(const std::string& name, ForceTerm term);
    void step() override;
    std::vector<Metric> metrics() const override;
    /// Total energy: kinetic + gravity + springs, J.
    double energy() const;
    /// The springs of the model.
    const std::vector<Spring>& springs() const { return springs_; }

protected:
    /// One step of scene().solver.method on the force field F(x, v).
    void integrate(const ForceField& field, double dt);

    std::vector<Spring> springs_;          ///< the springs
    std::vector<std::pair<int, ForceTerm>> forces_;  ///< (pass id, term)
    int integrate_pass_ = -1;              ///< pass id of the integrator
    int provot_pass_ = -1;                 ///< pass id of Provot's strain limit, −1 if off
    Rk4Workspace rk4_;                     ///< buffers of rk4Step()
    ImplicitEulerSolver implicit_;         ///< the implicit Euler stepper
    double initial_energy_ = 0.0;          ///< E at t = 0, J
    std::optional<DampedOscillator> analytic_;  ///< exact solution, when there is one
    Vec3 anchor_{0, 0, 0};                 ///< fixed end of the 1-D solution's line, m
    Vec3 axis_{0, -1, 0};                  ///< unit direction of that line
    mutable double max_error_ = 0.0;       ///< largest error against the analytic solution so far, m
};

}  // namespace clothlab
