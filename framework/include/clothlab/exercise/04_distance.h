/// @file 04_distance.h
/// @brief Stage 04 (Position Based Dynamics): the distance constraint (Distanz-Constraint).
///
/// The student writes these functions in `exercises/04_distance/distance.cpp`;
/// the task sheet is `exercises/04_distance/README.md`. Notation as on the slides:
/// p1, p2 predicted positions, w1, w2 inverse masses, d rest length, k stiffness in [0, 1].
#pragma once
#include <vector>

#include "clothlab/core/types.h"

namespace clothlab {

/// The corrections of one distance-constraint projection.
struct DistanceCorrection {
    Vec3 dp1;  ///< Δp1, m: add to p1
    Vec3 dp2;  ///< Δp2, m: add to p2
};

/// Exercise 4.1 — the cost function of the distance constraint (models a spring), as on the slides:
/// \f[ C(\vec p_1, \vec p_2) = |\vec p_1 - \vec p_2| - d \f]
/// Zero at the rest distance, positive when stretched, negative when compressed.
/// @param p1, p2  end points, m
/// @param d       rest length, m, d ≥ 0
/// @return        C, m (positive: stretched, negative: compressed)
double distanceConstraint(const Vec3& p1, const Vec3& p2, double d);

/// Exercise 4.2 — the gradient of C with respect to p1, \f$ \nabla_{\vec p_1} C \f$.
///
/// Requirements: it agrees with central finite differences of distanceConstraint() in p1; because C
/// depends only on the difference p1 − p2, \f$ \nabla_{\vec p_2} C = -\nabla_{\vec p_1} C \f$ (you return
/// the first one only). Coincident points (|p1 − p2| < 1e-12 m, degenerate: notation table): the direction is undefined,
/// return the zero vector, never NaN.
/// @param p1, p2  end points, m
/// @return        \f$ \nabla_{\vec p_1} C \f$ (dimensionless), or zero for coincident points
Vec3 distanceGradient(const Vec3& p1, const Vec3& p2);

/// Exercise 4.3 — projection of the distance constraint (Projektion des Constraint) with stiffness k.
///
/// Requirements (derive the corrections from them; the task sheet outlines how):
/// - both corrections lie along the constraint's gradient (the line through p1 and p2);
/// - with k = 1 one projection satisfies the constraint exactly: C(p1 + Δp1, p2 + Δp2) = 0;
///   with stiffness k it removes the fraction k of C, i.e. C afterwards is (1 − k)·C;
/// - no momentum is created: \f$ m_1\Delta\vec p_1 + m_2\Delta\vec p_2 = 0 \f$ with m_i = 1/w_i,
///   so a pinned end (w = 0) does not move and the other one moves the whole way;
/// - a satisfied constraint (C = 0) moves nothing.
/// Both pinned (w1 + w2 = 0) or coincident points (|p1 − p2| < 1e-12 m, degenerate: notation table):
/// zero corrections, never NaN.
/// @param p1, p2  end points, m
/// @param w1, w2  inverse masses, 1/kg (0: pinned)
/// @param d       rest length, m
/// @param k       stiffness in [0, 1] (per iteration, see iterationStiffness())
/// @return        Δp1, Δp2, m
DistanceCorrection projectDistanceConstraint(const Vec3& p1, const Vec3& p2, double w1, double w2, double d,
                                             double k);

/// Bonus 4.4a — the anchors of long-range attachments (tethers; Kim, Chentanez, Müller 2012), beyond the
/// slides and optional: every free particle is tied to the pinned particle nearest to it in the rest
/// state, so that no pull at the free end can take it farther from that pin than it was at rest.
///
/// Requirements: anchor[i] is the index of a pinned particle (w = 0) at the least rest distance
/// |rest_i − rest_a| from particle i, the lowest such index when several are equally near; −1 for a
/// pinned particle itself and for every particle when none is pinned.
/// @param rest  rest positions, 3 × N, m
/// @param w     inverse masses, N, 1/kg (0: pinned)
/// @return      anchor index per particle, N entries in [−1, N)
std::vector<int> tetherAnchors(const Matrix3X& rest, const VectorX& w);

/// Bonus 4.4b — one projection of a tether: the one-sided constraint \f$ C(\vec p) = |\vec p - \vec a| - L \le 0 \f$
/// between a free particle p and its anchor a (pinned, it never moves).
///
/// Requirements: a slack tether (|p − a| ≤ L) moves nothing; a taut one moves p straight towards a,
/// the least distance that makes C = 0 (no more); L = 0 pulls p onto a. Never NaN.
/// @param p       the free particle's predicted position, m
/// @param anchor  its anchor's position, m
/// @param L       the tether's length (the rest distance), m, L ≥ 0
/// @return        Δp, m: add to p
Vec3 projectTether(const Vec3& p, const Vec3& anchor, double L);

}  // namespace clothlab
