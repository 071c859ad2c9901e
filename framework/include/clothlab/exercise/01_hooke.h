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
/// \f[ \vec F_s = -k\,(\|\vec p_1-\vec p_0\| - l_0)\,\frac{\vec p_1-\vec p_0}{\|\vec p_1-\vec p_0\|} \f]
/// The force on p0 is the opposite, −F_s (Newton's third law).
/// If p0 and p1 coincide the direction is undefined: return the zero vector (never NaN).
/// @param p0  first end point, m
/// @param p1  second end point, m
/// @param k   stiffness (Federhärte), N/m, k ≥ 0
/// @param l0  rest length (Ruhelänge), m, l0 ≥ 0
/// @return    force on p1, N
Vec3 hookeForce(const Vec3& p0, const Vec3& p1, double k, double l0);

/// Exercise 1.2 — damping along the spring: the damping force acting on p1.
///
/// \f[ \vec F_d = -k_d\,\big((\vec v_1-\vec v_0)\cdot\hat d\big)\,\hat d,\qquad \hat d = \frac{\vec p_1-\vec p_0}{\|\vec p_1-\vec p_0\|} \f]
/// Only the relative velocity along the spring is damped. Coincident points: zero vector.
/// @param p0, p1  end points, m
/// @param v0, v1  their velocities, m/s
/// @param kd      damping coefficient, N s/m, kd ≥ 0
/// @return        damping force on p1, N (the force on p0 is its opposite)
Vec3 springDampingForce(const Vec3& p0, const Vec3& p1, const Vec3& v0, const Vec3& v1, double kd);

/// The total force on every particle as a function of the state: f = F(x, v).
/// Arguments: x (3 x N, m), v (3 x N, m/s), f (3 x N, N; overwritten).
using ForceField = std::function<void(const Matrix3X& x, const Matrix3X& v, Matrix3X& f)>;

/// Exercise 1.3 — explicit (forward) Euler step.
///
/// \f[ \vec a_i = w_i\,\vec F_i(x^n, v^n),\quad x_i^{n+1} = x_i^n + \Delta t\,v_i^n,\quad v_i^{n+1} = v_i^n + \Delta t\,\vec a_i \f]
/// Both updates use the old state. Particles with w_i = 0 (pinned) get no acceleration.
/// @param x      positions, 3 x N, m (updated in place)
/// @param v      velocities, 3 x N, m/s (updated in place)
/// @param w      inverse masses, N, 1/kg
/// @param force  evaluates the forces F(x, v), N
/// @param dt     time step Δt, s
void explicitEulerStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt);

/// Exercise 1.4 — symplectic (semi-implicit) Euler step.
///
/// \f[ v_i^{n+1} = v_i^n + \Delta t\,w_i\,\vec F_i(x^n, v^n),\qquad x_i^{n+1} = x_i^n + \Delta t\,v_i^{n+1} \f]
/// The position update uses the *new* velocity.
/// @param x, v, w, force, dt  as in explicitEulerStep()
void symplecticEulerStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt);

/// Exercise 1.5 — velocity Verlet step (second order).
///
/// \f[ v^{n+1/2} = v^n + \tfrac{\Delta t}{2}\,w\,F(x^n, v^n),\quad
///     x^{n+1} = x^n + \Delta t\,v^{n+1/2},\quad
///     v^{n+1} = v^{n+1/2} + \tfrac{\Delta t}{2}\,w\,F(x^{n+1}, v^{n+1/2}) \f]
/// Second order when F depends on the positions only; with velocity-dependent forces (damping)
/// the last kick uses \f$ v^{n+1/2} \f$ instead of \f$ v^{n+1} \f$ and the step is first order.
/// @param x, v, w, force, dt  as in explicitEulerStep()
void velocityVerletStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt);

}  // namespace clothlab
