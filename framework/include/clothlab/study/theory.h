/// @file theory.h
/// @brief What theory predicts about the stability of each integrator on a mass-spring system.
///
/// Linearised around a state, a mass-spring system oscillates in modes of angular frequency
/// \f$ \omega \f$ with \f$ \omega^2 \f$ the eigenvalues of \f$ M^{-1}K \f$ (K = −∂f/∂x, the stiffness
/// matrix). On one mode \f$ \ddot\xi = -\omega^2\xi \f$ the methods behave as follows (no damping):
/// - explicit Euler: amplitude × \f$ \sqrt{1+\omega^2\Delta t^2} \f$ per step — unstable for every Δt;
/// - symplectic Euler and velocity Verlet: bounded iff \f$ \omega\Delta t < 2 \f$ (for one mass m on one
///   spring k: \f$ k < 4m/\Delta t^2 \f$);
/// - RK4: bounded (slowly damped) iff \f$ \omega\Delta t < 2\sqrt2 \f$;
/// - implicit (backward) Euler: amplitude × \f$ 1/\sqrt{1+\omega^2\Delta t^2} \f$ — stable for every Δt.
/// Provot (1995) estimates the critical stiffness from the natural period \f$ 2\pi\sqrt{m/k} \f$ of one
/// particle on one spring: the step must stay below half of it, \f$ T_0 \approx \pi\sqrt{m/k} \f$ (the T0
/// of the course slides and docs/mfn.md), i.e. \f$ k_{krit} \approx m\,\pi^2/\Delta t^2 \f$.
/// (The course slides print \f$ m\,\Delta t^2/\pi^2 \f$ — upside down: a smaller step allows a stiffer
/// spring, not a softer one.) The whole system is limited by its fastest mode, \f$ \omega_{max} \f$.
#pragma once
#include <string>

#include "clothlab/core/scene.h"

namespace clothlab {

/// The largest angular frequency \f$ \omega_{max} = \sqrt{\lambda_{max}(M^{-1}K)} \f$ of the scene's
/// mass-spring model at its initial state, rad/s, with \f$ K = -\partial f/\partial x \f$ of the springs
/// (the Jacobian of addSpringJacobians()) over the free particles. Computed with Eigen: a dense
/// symmetric eigensolver on \f$ M^{-1/2} K M^{-1/2} \f$ up to 900 unknowns, power iteration above.
/// For a single spring at rest this is \f$ \sqrt{k/m} \f$.
/// @param scene  a scene with model spring, chain or cloth (its springs as makeSimulation() builds them)
/// @return       ω_max, rad/s (0 if there are no springs or no free particles)
double maxAngularFrequency(const Scene& scene);

/// The largest stable time step theory predicts for `method` at angular frequency ω, s:
/// 2/ω for symplectic_euler and velocity_verlet, 2√2/ω for rk4, +∞ for implicit_euler,
/// 0 for explicit_euler (unstable for every Δt without damping), and −1 for a method this
/// table does not know (e.g. position-based methods).
/// @param method  the method
/// @param omega   angular frequency ω > 0, rad/s
double theoreticalCriticalDt(Method method, double omega);

/// Provot's critical stiffness \f$ k_{krit} = m\,\pi^2/\Delta t^2 \f$, N/m.
/// @param m   particle mass, kg
/// @param dt  time step, s
double provotCriticalStiffness(double m, double dt);

/// A copy of the scene with its stiffness set to k: spring.k or chain.k, or, for a cloth, every
/// spring group scaled by the same factor so that the structural springs get k (the ratios between
/// structural, shear and bending stay). Scales ω_max by \f$ \sqrt{k/k_{old}} \f$.
/// @param scene  the scene
/// @param k      the new (structural) stiffness, N/m, > 0
Scene withStiffness(const Scene& scene, double k);

/// The (structural) stiffness of the scene, N/m: spring.k, chain.k, or the cloth's structural k
/// (or the first enabled group's).
/// @param scene  the scene
double sceneStiffness(const Scene& scene);

}  // namespace clothlab
