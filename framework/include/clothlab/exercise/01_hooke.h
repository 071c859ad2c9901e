/// @file 01_hooke.h
/// @brief Stage 01 (Masse-Feder-Systeme): the Hooke spring and three time integrators.
///
/// The student writes these functions in `exercises/01_hooke/hooke.cpp`;
/// the task sheet is `exercises/01_hooke/README.md`. Notation as on the slides:
/// p0, p1 spring end points, k Federhärte (stiffness), l0 Ruhelänge (rest length),
/// x positions, v velocities, w inverse masses, Δt the time step.
#pragma once
#include <functional>

#include "clothlab/core/types.h"

namespace clothlab {

/// Exercise 1.1 — Hooke's law (Gesetz von Hooke): the spring force acting on p1.
///
/// Requirements (the task sheet has the slide's formula, the graded tests check each one):
/// - the force is minus the gradient of the spring energy with respect to p1,
///   \f$ \vec F_s = -\nabla_{\vec p_1} E \f$ with \f$ E = \tfrac{k}{2}\,(\|\vec p_1-\vec p_0\| - l_0)^2 \f$;
/// - it acts along the spring, pulls p1 back towards p0 when the spring is stretched, pushes it
///   away when compressed, and vanishes at the rest length (Ruhelänge);
/// - its magnitude is linear in the deformation \f$ \Delta l = \|\vec p_1-\vec p_0\| - l_0 \f$;
/// - the force on p0 is the opposite (Newton's third law).
/// If p0 and p1 coincide (|p1 − p0| < 1e-12 m, degenerate: notation table) the direction is undefined:
/// return the zero vector, never NaN.
/// @param p0  first end point, m
/// @param p1  second end point, m
/// @param k   stiffness (Federhärte), N/m, k ≥ 0
/// @param l0  rest length (Ruhelänge), m, l0 ≥ 0
/// @return    force on p1, N
Vec3 hookeForce(const Vec3& p0, const Vec3& p1, double k, double l0);

/// Exercise 1.2 — damping along the spring: the damping force acting on p1.
///
/// Requirements:
/// - it depends only on the relative velocity v1 − v0 (a common motion of both ends is not damped);
/// - only the component of that relative velocity along the spring is damped: motion across the
///   spring (a rotation) gets no force, and the force itself points along the spring;
/// - it opposes that component and is linear in it, with coefficient kd (a relative speed of 1 m/s
///   along the spring gives kd newtons);
/// - so it never adds energy: the power it does on the pair is ≤ 0.
/// Coincident points (|p1 − p0| < 1e-12 m, degenerate: notation table): the zero vector, never NaN.
/// @param p0, p1  end points, m
/// @param v0, v1  their velocities, m/s
/// @param kd      damping coefficient, N s/m, kd ≥ 0
/// @return        damping force on p1, N (the force on p0 is its opposite)
Vec3 springDampingForce(const Vec3& p0, const Vec3& p1, const Vec3& v0, const Vec3& v1, double kd);

/// The total force on every particle as a function of the state: f = F(x, v).
/// Arguments: x (3 x N, m), v (3 x N, m/s), f (3 x N, N; overwritten).
using ForceField = std::function<void(const Matrix3X& x, const Matrix3X& v, Matrix3X& f)>;

/// Exercise 1.3 — one step of the explicit (forward) Euler method for
/// \f$ \dot x = v,\ \dot v = a = w\,F(x, v) \f$.
///
/// Requirements: every derivative is taken at the old state \f$ (x^n, v^n) \f$, so the force is
/// evaluated once per step; the acceleration of particle i is \f$ w_i \vec F_i \f$, so a pinned
/// particle (w_i = 0) keeps its velocity (and, at rest, its position); first order in Δt (halving
/// Δt halves the error). On an undamped oscillator the energy grows every step.
/// @param x      positions, 3 x N, m (updated in place)
/// @param v      velocities, 3 x N, m/s (updated in place)
/// @param w      inverse masses, N, 1/kg
/// @param force  evaluates the forces F(x, v), N
/// @param dt     time step Δt, s
void explicitEulerStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt);

/// Exercise 1.4 — one step of the symplectic (semi-implicit) Euler method.
///
/// Requirements: the velocity is advanced first, with the force at the old state \f$ (x^n, v^n) \f$
/// (one force evaluation per step); the position is then advanced with the velocity *just computed*.
/// First order in Δt, but the energy of an undamped oscillator stays bounded (no drift), and
/// momentum and angular momentum of internal forces are kept. Pinned particles as in explicitEulerStep().
/// @param x, v, w, force, dt  as in explicitEulerStep()
void symplecticEulerStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt);

/// Exercise 1.5 — one step of velocity Verlet (second order).
///
/// Requirements, for forces that depend on the positions only (\f$ a^n = w\,F(x^n) \f$): the new position
/// \f$ x^{n+1} \f$ agrees with the Taylor expansion of \f$ x(t^n + \Delta t) \f$ up to and including its
/// \f$ \Delta t^2 \f$ term, taken with \f$ x^n, v^n, a^n \f$; the velocity changes by \f$ \Delta t \f$ times the
/// mean of \f$ a^n \f$ and \f$ a^{n+1} = w\,F(x^{n+1}) \f$ (the trapezoidal rule). The force is evaluated
/// exactly twice per step, at the old positions and at the new ones. Convention for velocity-dependent
/// forces (damping): the second evaluation receives the velocity that already contains the \f$a^n\f$ half of
/// the velocity change and not yet the \f$a^{n+1}\f$ half (the method is then first order).
/// Second order (halving Δt quarters the error), energy bounded; pinned particles as in explicitEulerStep().
/// @param x, v, w, force, dt  as in explicitEulerStep()
void velocityVerletStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt);

}  // namespace clothlab
