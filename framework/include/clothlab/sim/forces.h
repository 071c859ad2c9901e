/// @file forces.h
/// @brief Force terms of the force-based (mass-spring) methods. Each adds into f (3 x N, newtons).
#pragma once
#include <vector>

#include "clothlab/core/spring.h"
#include "clothlab/core/types.h"

namespace clothlab {

/// Gravity: \f$ \vec f_i \mathrel{+}= m_i\,\vec g \f$ with \f$ m_i = 1/w_i \f$; pinned particles (w_i = 0) get none.
/// @param w  inverse masses, N, 1/kg
/// @param g  gravitational acceleration, m/s²
/// @param f  forces, 3 x N, N (added to)
void addGravityForces(const VectorX& w, const Vec3& g, Matrix3X& f);

/// Global (air) damping: \f$ \vec f_i \mathrel{+}= -c\,\vec v_i \f$.
/// @param v  velocities, 3 x N, m/s
/// @param c  damping coefficient, N s/m
/// @param f  forces, 3 x N, N (added to)
void addVelocityDamping(const Matrix3X& v, double c, Matrix3X& f);

/// All springs: for spring (i, j), \f$ \vec F = \f$ hookeForce(x_i, x_j, k, l0) + springDampingForce(...)
/// acts on j, \f$ -\vec F \f$ on i (stage 01 functions).
/// @param springs  the springs
/// @param x        positions, 3 x N, m
/// @param v        velocities, 3 x N, m/s
/// @param f        forces, 3 x N, N (added to)
void addSpringForces(const std::vector<Spring>& springs, const Matrix3X& x, const Matrix3X& v, Matrix3X& f);

/// Kinetic energy \f$ \sum_i \tfrac12 m_i |\vec v_i|^2 \f$ over particles with w_i > 0, J.
double kineticEnergy(const VectorX& w, const Matrix3X& v);

/// Gravitational potential energy \f$ -\sum_i m_i\,\vec g\cdot\vec x_i \f$ over particles with w_i > 0, J.
double gravityEnergy(const VectorX& w, const Matrix3X& x, const Vec3& g);

/// Elastic energy of the springs \f$ \sum \tfrac12 k (|\vec x_j-\vec x_i| - l_0)^2 \f$, J.
double springEnergy(const std::vector<Spring>& springs, const Matrix3X& x);

}  // namespace clothlab
