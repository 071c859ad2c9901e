/// @file 04_distance.h
/// @brief Stage 04 (Position Based Dynamics): the distance constraint (Distanz-Constraint).
///
/// The student writes these functions in `exercises/04_distance/distance.cpp`;
/// the task sheet is `exercises/04_distance/README.md`. Notation as on the slides:
/// p1, p2 predicted positions, w1, w2 inverse masses, d rest length, k stiffness in [0, 1].
#pragma once
#include "clothlab/core/types.h"

namespace clothlab {

/// The corrections of one distance-constraint projection.
struct DistanceCorrection {
    Vec3 dp1;  ///< Δp1, m: add to p1
    Vec3 dp2;  ///< Δp2, m: add to p2
};

/// Exercise 4.1 — the cost function of the distance constraint (models a spring):
/// \f[ C(\vec p_1, \vec p_2) = |\vec p_1 - \vec p_2| - d \f]
/// @param p1, p2  end points, m
/// @param d       rest length, m, d ≥ 0
/// @return        C, m (positive: stretched, negative: compressed)
double distanceConstraint(const Vec3& p1, const Vec3& p2, double d);

/// Exercise 4.2 — the gradient of C with respect to p1:
/// \f[ \nabla_{\vec p_1} C = \frac{\vec p_1 - \vec p_2}{|\vec p_1 - \vec p_2|} = \vec n,
///     \qquad \nabla_{\vec p_2} C = -\vec n \f]
/// Coincident points (|p1 − p2| < 1e-12 m): the direction is undefined, return the zero vector.
/// @param p1, p2  end points, m
/// @return        unit vector n (dimensionless), or zero for coincident points
Vec3 distanceGradient(const Vec3& p1, const Vec3& p2);

/// Exercise 4.3 — projection of the distance constraint (slides, mass-weighted):
/// \f[ \Delta\vec p_1 = -\frac{w_1}{w_1 + w_2}\,(|\vec p_1 - \vec p_2| - d)\,
///        \frac{\vec p_1 - \vec p_2}{|\vec p_1 - \vec p_2|}\,k,\qquad
///     \Delta\vec p_2 = +\frac{w_2}{w_1 + w_2}\,(|\vec p_1 - \vec p_2| - d)\,
///        \frac{\vec p_1 - \vec p_2}{|\vec p_1 - \vec p_2|}\,k \f]
/// With k = 1 one projection satisfies the constraint exactly; Σ m_i Δp_i = 0 (no momentum is
/// created). Both pinned (w1 + w2 = 0) or coincident points: zero corrections, never NaN.
/// @param p1, p2  end points, m
/// @param w1, w2  inverse masses, 1/kg (0: pinned)
/// @param d       rest length, m
/// @param k       stiffness in [0, 1] (per iteration, see iterationStiffness())
/// @return        Δp1, Δp2, m
DistanceCorrection projectDistanceConstraint(const Vec3& p1, const Vec3& p2, double w1, double w2, double d,
                                             double k);

}  // namespace clothlab
