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
/// Over the particles with w_i > 0 (m_i = 1/w_i):
/// \f[ \vec x_{cm} = \frac{\sum_i m_i \vec x_i}{\sum_i m_i},\quad
///     \vec v_{cm} = \frac{\sum_i m_i \vec v_i}{\sum_i m_i},\quad
///     \vec L = \sum_i \vec r_i \times (m_i \vec v_i),\ \vec r_i = \vec x_i - \vec x_{cm},\quad
///     I = \sum_i m_i\,\tilde r_i \tilde r_i^T \f]
/// \f[ \vec\omega = I^{-1}\vec L,\qquad
///     \Delta\vec v_i = \vec v_{cm} + \vec\omega\times\vec r_i - \vec v_i,\qquad
///     \vec v_i \leftarrow \vec v_i + k_{damping}\,\Delta\vec v_i \f]
/// (\f$\tilde r\f$ is the cross-product matrix, \f$\tilde r\,\vec a = \vec r\times\vec a\f$.)
/// If I is singular (all particles on one line, or one particle) use its pseudo-inverse, i.e. no
/// rotation about the line. Pinned particles (w_i = 0) keep their velocity. k_damping = 0: no change.
/// @param x         positions, 3 x N, m
/// @param v         velocities, 3 x N, m/s (changed in place)
/// @param w         inverse masses, N, 1/kg
/// @param kDamping  damping coefficient k_damping in [0, 1] (1: only rigid motion survives)
void dampVelocities(const Matrix3X& x, Matrix3X& v, const VectorX& w, double kDamping);

/// Exercise 3.2 — the stiffness a constraint applies in each of n solver iterations.
///
/// Projecting a constraint with stiffness k' in each of n iterations leaves the error
/// \f$(1-k')^n\f$ of the original one; to make that equal to \f$1-k\f$ (the error k leaves in one
/// projection) independent of n:
/// \f[ k' = 1 - (1 - k)^{1/n} \f]
/// n = 0 (no iterations): return k. k = 1 stays 1; k = 0 stays 0.
/// @param k           stiffness in [0, 1]
/// @param iterations  number of solver iterations n ≥ 0
/// @return            per-iteration stiffness k' in [0, 1]
double iterationStiffness(double k, int iterations);

/// Exercise 3.3 — one PBD time step, lines (5)–(16) of the slides:
/// \f[ (5)\ \vec v_i \leftarrow \vec v_i + \Delta t\,w_i\,\vec f_{ext}(\vec x_i) \qquad
///     (6)\ \mathrm{dampVelocities}(\vec v_1..\vec v_N) \qquad
///     (7)\ \vec p_i \leftarrow \vec x_i + \Delta t\,\vec v_i \f]
/// \f[ (8)\ \mathrm{generateCollisionConstraints}(\vec x_i\to\vec p_i) \qquad
///     (9\text{–}11)\ \text{solverIterations times: projectConstraints}(\vec p) \f]
/// \f[ (13)\ \vec v_i \leftarrow (\vec p_i - \vec x_i)/\Delta t \qquad
///     (14)\ \vec x_i \leftarrow \vec p_i \qquad
///     (16)\ \mathrm{velocityUpdate}(\vec v_1..\vec v_N) \f]
/// Empty callbacks are skipped (no forces, no collisions, no constraints, no velocity update).
/// @param P           particles (x, v changed; p holds the prediction afterwards)
/// @param callbacks   forces, collision generation, constraint sweep, velocity update
/// @param kDamping    coefficient of dampVelocities in [0, 1]
/// @param iterations  solverIterations ≥ 0
/// @param dt          time step Δt > 0, s
void pbdStep(PbdParticles& P, const PbdCallbacks& callbacks, double kDamping, int iterations, double dt);

}  // namespace clothlab
