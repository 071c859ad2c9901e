/// @file rk4.h
/// @brief Classical Runge–Kutta (fourth order), the framework's reference integrator.
#pragma once
#include "clothlab/exercise/01_hooke.h"

namespace clothlab {

/// One RK4 step of x' = v, v' = w F(x, v):
/// \f[ y^{n+1} = y^n + \tfrac{\Delta t}{6}(k_1 + 2k_2 + 2k_3 + k_4) \f]
/// with the four stage slopes at t, t + Δt/2 (twice) and t + Δt.
/// @param x, v   positions and velocities, 3 x N (updated in place)
/// @param w      inverse masses, N, 1/kg
/// @param force  the force field F(x, v), N
/// @param dt     time step, s
void rk4Step(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt);

}  // namespace clothlab
