/// @file energy.h
/// @brief The energies of the run report: kinetic, gravitational and elastic (springs), in joules.
#pragma once
#include <vector>

#include "clothlab/core/spring.h"
#include "clothlab/core/types.h"

namespace clothlab {

/// Kinetic energy \f$ \sum_i \tfrac12 m_i |\vec v_i|^2 \f$ over particles with w_i > 0, J.
/// @param w  inverse masses, N, 1/kg
/// @param v  velocities, 3 x N, m/s
double kineticEnergy(const VectorX& w, const Matrix3X& v);

/// Gravitational potential energy \f$ -\sum_i m_i\,\vec g\cdot\vec x_i \f$ over particles with w_i > 0, J.
/// @param w  inverse masses, N, 1/kg
/// @param x  positions, 3 x N, m
/// @param g  gravitational acceleration, m/s²
double gravityEnergy(const VectorX& w, const Matrix3X& x, const Vec3& g);

/// Elastic energy of the springs \f$ \sum_s \tfrac12 k_s (\|\vec x_j-\vec x_i\| - l_{0,s})^2 \f$, J.
/// @param springs  the springs
/// @param x        positions, 3 x N, m
double springEnergy(const std::vector<Spring>& springs, const Matrix3X& x);

}  // namespace clothlab
