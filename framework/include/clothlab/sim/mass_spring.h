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

/// A chain of n particles along `direction`, links of rest length l0, particle 0 pinned
/// (a one-dimensional mass-spring network: it runs on stage 02's force functions). With `end`, the
/// last particle is pinned there too and the chain starts as a V below the anchors: particle i at arc
/// length i l0 along anchor → apex → end, the apex on the anchors' perpendicular bisector, straight
/// below their midpoint (−y, or −x if the anchors are above each other), (n−1) l0 / 2 from each anchor.
MassSpringModel makeChain(const ChainSpec& spec);

/// A cloth (stage 02): particles from makeClothGeometry(); a grid's springs from makeClothSprings()
/// (structural, shear and bending as the scene's `springs` enable them), a mesh's from makeMeshSprings().
MassSpringModel makeCloth(const Scene& scene);

/// The springs of a mesh cloth: a structural spring along every edge (uniqueEdges()) and a bending
/// spring between the two vertices opposite every interior edge (oppositeVertices()); a mesh has no
/// separate shear springs. Rest lengths from x; k and kd from the enabled groups of `types`.
/// @param x          particle positions at rest, 3 x N, m
/// @param triangles  the mesh
/// @param types      springs.structural and springs.bending (springs.shear is not used)
/// @return           the springs
std::vector<Spring> makeMeshSprings(const Matrix3X& x, const std::vector<Eigen::Vector3i>& triangles, const ClothSprings& types);

/// The 1-D analytic solution of the single-spring scene, when the motion stays on the
/// spring's line (start − anchor, initial velocity and gravity all parallel).
std::optional<DampedOscillator> singleSpringAnalytic(const Scene& scene);

/// Time integration of a mass-spring model (Masse-Feder-System), one step:
/// \f[ (1)\ \vec F(\vec x, \vec v) = \textstyle\sum \text{force passes} \qquad
///     (2)\ \vec x, \vec v \leftarrow \text{one step of the integrator on } \vec F \qquad
///     (3)\ \text{Provot's strain limit (if enabled)} \f]
/// The force passes are the students' code: on the single spring stage 01's hookeForce() and
/// springDampingForce() on the hanging particle; on a chain or cloth stage 02's
/// addClothExternalForces() (gravity, air damping) and addClothSpringForces(). The integrators are
/// stage 01's (explicit_euler, symplectic_euler, velocity_verlet) and the framework's rk4 and
/// implicit_euler.
class MassSpringSimulation : public Simulation {
public:
    /// A force term: adds its forces into f.
    using ForceTerm = std::function<void(const Matrix3X& x, const Matrix3X& v, Matrix3X& f)>;

    /// @param scene  a scene with model spring, chain or cloth and a force-based method
    /// @param model  its particles and springs
    MassSpringSimulation(const Scene& scene, MassSpringModel model);
    /// One step (see the class comment).
    /// @throws SolverFailure when implicit Euler cannot solve its linear system (the state is unchanged)
    void step() override;
    const State& state() const override { return state_; }
    State& state() override { return state_; }
    /// The springs of the model.
    const std::vector<Spring>& springs() const { return springs_; }
    /// Distance between the hanging particle and the analytic solution, m (0 without one).
    double analyticError() const;
    /// A chain between two anchors: the largest distance of a particle from the catenary with the
    /// same end points and arc length (Catenary), as a fraction of the span |end − anchor| (1);
    /// −1 for any other scene.
    double catenaryError() const;

    /// The implicit Euler stepper (method implicit_euler), e.g. to choose its linear solver.
    ImplicitEulerSolver& implicitSolver() { return implicit_; }

protected:
    double elasticEnergy() const override;
    /// error and max_error against the analytic solution, when the scene has one; catenary_error for a
    /// chain between two anchors; with implicit Euler solve_residual (|b − A Δv|/|b| of the last step)
    /// and solve_iterations (CG, 0 for Cholesky).
    void addMetrics(std::vector<Metric>& m) const override;

private:
    /// Adds a force pass named `name` (shown in the timing report).
    void addForce(const std::string& name, ForceTerm term);
    /// Step (2): one step of scene().solver.method on the force field F(x, v).
    void integrate(double dt);

    State state_;                          ///< particles
    std::vector<Spring> springs_;          ///< the springs
    std::vector<std::pair<int, ForceTerm>> forces_;  ///< (pass id, term)
    ForceField field_;                     ///< F(x, v): the sum of the force passes, each timed
    int integrate_pass_ = -1;              ///< pass id of the integrator
    int provot_pass_ = -1;                 ///< pass id of Provot's strain limit, −1 if off
    Rk4Workspace rk4_;                     ///< buffers of rk4Step()
    ImplicitEulerSolver implicit_;         ///< the implicit Euler stepper
    std::optional<DampedOscillator> analytic_;  ///< exact solution, when there is one
    std::optional<Catenary> catenary_;     ///< a chain between two anchors: its catenary
    Vec3 anchor_{0, 0, 0};                 ///< fixed end of the 1-D solution's line, m
    Vec3 axis_{0, -1, 0};                  ///< unit direction of that line
    double max_error_ = 0.0;               ///< largest error against the analytic solution after any step, m
};

}  // namespace clothlab
