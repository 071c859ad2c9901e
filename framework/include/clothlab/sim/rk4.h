/// @file rk4.h
/// @brief Classical Runge–Kutta (fourth order), the framework's reference integrator.
#pragma once
#include "clothlab/exercise/01_hooke.h"

namespace clothlab {

/// Buffers of rk4Step(), kept between steps so that a step allocates no memory.
/// (Allocating and freeing a dozen 3 x N temporaries per step made the C library hand the
/// heap top back to the kernel and fault it in again on every step: 30x slower for N = 1000.)
struct Rk4Workspace {
    Matrix3X f;       ///< forces of the current stage, 3 x N, N
    Matrix3X xs;      ///< positions at which the current stage is evaluated, m
    Matrix3X vs;      ///< velocities at which the current stage is evaluated, m/s
    Matrix3X dx;      ///< weighted sum k1 + 2 k2 + 2 k3 + k4 of the position slopes, m/s
    Matrix3X dv;      ///< weighted sum of the velocity slopes, m/s²
};

/// One RK4 step of x' = v, v' = w F(x, v):
/// \f[ y^{n+1} = y^n + \tfrac{\Delta t}{6}(k_1 + 2k_2 + 2k_3 + k_4) \f]
/// with the four stage slopes at t, t + Δt/2 (twice) and t + Δt.
/// @param x, v   positions and velocities, 3 x N (updated in place)
/// @param w      inverse masses, N, 1/kg
/// @param force  the force field F(x, v), N
/// @param dt     time step, s
/// @param ws     buffers reused between steps (resized as needed)
void rk4Step(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt, Rk4Workspace& ws);

/// rk4Step() with buffers of its own (allocates them on every call).
/// @param x, v, w, force, dt  as above
void rk4Step(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt);

}  // namespace clothlab
