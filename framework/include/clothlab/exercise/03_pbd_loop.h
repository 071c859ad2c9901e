/// @file 03_pbd_loop.h
/// @brief Stage 03 (Position Based Dynamics): the PBD time step, lines (5)–(16) of the slides.
///
/// The student writes these functions in `exercises/03_pbd_loop/pbd_loop.cpp`;
/// the task sheet is `exercises/03_pbd_loop/README.md`. Notation as on the slides
/// (Müller, Heidelberger, Hennix, Ratcliff 2007): x positions, p predicted positions (geschätzte
/// Positionen), v velocities, w = 1/m inverse masses, Δt the time step, k stiffness in [0, 1].
///
/// The loop does not know which constraints exist: the framework (or a test) hands it the
/// callbacks of PbdCallbacks. That is how a scene without bending never calls the bending code,
/// and how the graded tests of this stage use constraints written in the test.
#pragma once
#include <functional>

#include "clothlab/core/state.h"
#include "clothlab/core/types.h"

namespace clothlab {

/// The particles of a PBD simulation (slides: Massepartikel with x_i, p_i, w_i, v_i): the State
/// (positions x_i in m, velocities v_i in m/s, inverse masses w_i = 1/m_i in 1/kg with w_i = 0 for a
/// pinned particle, time t in s) plus the predicted positions p_i.
struct PbdParticles : State {
    Matrix3X p;  ///< predicted positions p_i, 3 x N, m (scratch space of the step)
};

/// What one PBD step calls besides the student's own code. Every callback may be empty
/// (an empty std::function): then that line of the algorithm is skipped.
struct PbdCallbacks {
    /// Line (5): adds the external forces f_ext(x_i) (gravity, wind, ...) into f.
    /// Arguments: x (3 x N, m), v (3 x N, m/s), f (3 x N, N; zero on entry, added to).
    std::function<void(const Matrix3X& x, const Matrix3X& v, Matrix3X& f)> externalForces;
    /// Line (8): generateCollisionConstraints(x_i → p_i) for every particle, remembered by the
    /// caller for the projections and for velocityUpdate. Arguments: x, p (3 x N, m).
    std::function<void(const Matrix3X& x, const Matrix3X& p)> generateCollisionConstraints;
    /// Line (10): projectConstraints(C_1, ..., C_{M+M_coll}, p_1, ..., p_N): one sweep over all
    /// constraints (the scene's and the collision constraints), moving p in place.
    /// Argument: p (3 x N, m).
    std::function<void(Matrix3X& p)> projectConstraints;
    /// Line (16): velocityUpdate(v_1, ..., v_N): friction and restitution of the particles in
    /// contact. Arguments: x (3 x N, m, the new positions), v (3 x N, m/s, changed in place).
    std::function<void(const Matrix3X& x, Matrix3X& v)> velocityUpdate;
};

/// Exercise 3.1 — dampVelocities (paper, section 3.5): damp only the motion that deviates from
/// the rigid motion of the whole body, so a rigidly moving or spinning cloth is not slowed down.
///
/// The body is the set of free particles (w_i > 0, m_i = 1/w_i). Its rigid motion is the velocity
/// field \f$ \vec v_{cm} + \vec\omega\times(\vec x_i - \vec x_{cm}) \f$ with the same linear and
/// angular momentum (about the centre of mass) as the particles. Requirements:
/// - a velocity field that already is a rigid motion (translation plus spin) is unchanged;
/// - linear and angular momentum of the free particles are unchanged for every k_damping;
/// - each particle's deviation from the rigid motion shrinks by exactly the factor 1 − k_damping;
/// - where the momenta do not fix ω (the inertia is singular: all free particles on one line, or a
///   single one), take the ω without a component about the axes of zero inertia (no spin about the line);
/// - pinned particles (w_i = 0) keep their velocity; k_damping = 0 changes nothing; never NaN.
/// @param x         positions, 3 x N, m
/// @param v         velocities, 3 x N, m/s (changed in place)
/// @param w         inverse masses, N, 1/kg
/// @param kDamping  damping coefficient k_damping in [0, 1] (1: only rigid motion survives)
void dampVelocities(const Matrix3X& x, Matrix3X& v, const VectorX& w, double kDamping);

/// Exercise 3.2 — the stiffness k' a constraint applies in each of n solver iterations.
///
/// One projection with stiffness k removes the fraction k of a constraint's error (for a linear
/// constraint), leaving 1 − k. Requirement: n projections with k' each leave the same error as one
/// projection with k, for every n ≥ 1, so that the result does not depend on the iteration count.
/// n = 0 (no iterations): return k. k = 1 stays 1; k = 0 stays 0.
/// @param k           stiffness in [0, 1]
/// @param iterations  number of solver iterations n ≥ 0
/// @return            per-iteration stiffness k' in [0, 1]
double iterationStiffness(double k, int iterations);

/// Exercise 3.3 — one PBD time step: lines (5)–(16) of the slides' algorithm (reproduced on the
/// task sheet), in the slides' order.
///
/// Where the callbacks come in: line (5) asks externalForces for f_ext (f is 3 x N and zero on entry);
/// line (6) is your dampVelocities() with kDamping; line (8) passes the positions and the predictions
/// to generateCollisionConstraints; lines (9)–(11) call projectConstraints `iterations` times; line (16)
/// passes the new positions and velocities to velocityUpdate. Empty callbacks are skipped (no forces,
/// no collisions, no constraints, no velocity update).
/// Requirements: without constraints a particle falls as with symplectic Euler (error g t Δt/2 against
/// the parabola); a pinned particle (w = 0) never moves; zero iterations give the plain prediction;
/// the damping acts before the prediction; afterwards P.p holds the (projected) prediction.
/// @param P           particles (x, v changed; p holds the prediction afterwards)
/// @param callbacks   forces, collision generation, constraint sweep, velocity update
/// @param kDamping    coefficient of dampVelocities in [0, 1]
/// @param iterations  solverIterations ≥ 0
/// @param dt          time step Δt > 0, s
void pbdStep(PbdParticles& P, const PbdCallbacks& callbacks, double kDamping, int iterations, double dt);

}  // namespace clothlab
