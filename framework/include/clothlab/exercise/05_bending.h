/// @file 05_bending.h
/// @brief Stage 05 (Position Based Dynamics): the bending constraint (Biege-Constraint) and its stencils.
///
/// The student writes these functions in `exercises/05_bending/bending.cpp`;
/// the task sheet is `exercises/05_bending/README.md`. Notation as on the slides and in
/// Müller et al. 2007, appendix A: two triangles (p1, p3, p2) and (p1, p2, p4) share the edge
/// p1–p2; positions are taken relative to p1 (so p1 = 0 in the formulas), with the normals
/// \f[ \vec n_1 = \frac{\vec p_2\times\vec p_3}{|\vec p_2\times\vec p_3|},\qquad
///     \vec n_2 = \frac{\vec p_2\times\vec p_4}{|\vec p_2\times\vec p_4|},\qquad d = \vec n_1\cdot\vec n_2 \f]
/// the dihedral angle \f$ \varphi = \arccos(d) \f$ and the cost \f$ C = \varphi - \varphi_0 \f$.
/// With this convention a flat stencil (p3 and p4 on opposite sides of the edge) has d = −1, i.e. φ = π.
///
/// Numerically, φ and sin φ are computed as
/// \f[ \sin\varphi = |\vec n_1\times\vec n_2|,\qquad \varphi = \operatorname{atan2}(\sin\varphi,\ d) \f]
/// and not as \f$\sqrt{1-d^2}\f$ and arccos(d), which are the same numbers in exact arithmetic.
/// Cloth is mostly nearly flat, d ≈ −1, and there 1 − d² is the difference of two nearly equal
/// numbers (cancellation): the rounding error of d (about 1e-16) becomes a relative error of about
/// 1e-16/(1 − d²) in 1 − d² (1e-6 at φ = π − 1e-5, 1e-4 near the cut-off sin φ = 1e-6), and a crease
/// pressed flat, far from its rest angle, is moved by 0.1–0.5 m, so by up to 1e-4 m to the wrong place.
/// \f$|\vec n_1\times\vec n_2|\f$ is computed from the normals directly and keeps a relative error of
/// about 1e-16/sin φ; atan2 is accurate at every angle, while arccos has an infinite slope at d = ±1.
#pragma once
#include <vector>

#include <Eigen/Core>

#include "clothlab/core/types.h"

namespace clothlab {

/// d = n1·n2, sin φ and the gradients q_i = ∂d/∂p_i (appendix A of Müller et al. 2007).
struct BendingGradients {
    double d = -1.0;     ///< n1·n2, clamped to [−1, 1] (dimensionless)
    double sinPhi = 0.0; ///< sin φ = |n1 × n2| in [0, 1], computed directly, not as sqrt(1 − d²) (dimensionless)
    Vec3 q1{0, 0, 0};    ///< ∂d/∂p1, 1/m
    Vec3 q2{0, 0, 0};    ///< ∂d/∂p2, 1/m
    Vec3 q3{0, 0, 0};    ///< ∂d/∂p3, 1/m
    Vec3 q4{0, 0, 0};    ///< ∂d/∂p4, 1/m
    bool valid = false;  ///< false for a zero-area triangle (normals undefined): d = −1, sinPhi = 0, all q zero
};

/// The corrections of one bending projection.
struct BendingCorrection {
    Vec3 dp1{0, 0, 0};  ///< Δp1, m
    Vec3 dp2{0, 0, 0};  ///< Δp2, m
    Vec3 dp3{0, 0, 0};  ///< Δp3, m
    Vec3 dp4{0, 0, 0};  ///< Δp4, m
};

/// One bending constraint: an interior edge p1–p2 and the two opposite vertices.
struct BendingStencil {
    int i1 = 0;          ///< particle of the shared edge
    int i2 = 0;          ///< the other particle of the shared edge
    int i3 = 0;          ///< opposite vertex in the first triangle
    int i4 = 0;          ///< opposite vertex in the second triangle
    double phi0 = 0.0;   ///< rest angle φ0 = atan2(sin φ, d) = arccos(d) of the initial shape, rad (π: flat)
};

/// Exercise 5.1 — d = n1·n2, \f$\sin\varphi = |\vec n_1\times\vec n_2|\f$ (not \f$\sqrt{1-d^2}\f$:
/// see the top of this file) and the q-vectors \f$ \vec q_i = \partial d/\partial\vec p_i \f$ (appendix A).
///
/// Requirements: every component of every q_i agrees with central finite differences of d; since d
/// does not change when the whole stencil is translated, \f$ \vec q_1+\vec q_2+\vec q_3+\vec q_4 = 0 \f$;
/// the q_i rotate with the stencil and scale as 1/length. The q-vectors printed on the slides and in the
/// paper follow the paper's conventions (the task sheet shows them): check their sign against finite
/// differences of d before you use any of them.
/// Zero-area triangles (|p2 × p3| or |p2 × p4| below 1e-12 m², positions relative to p1) and coincident
/// points (degenerate: notation table): valid = false, d = −1, sinPhi = 0 and all q zero (never NaN). d is clamped to [−1, 1].
/// @param p1, p2  the shared edge, m
/// @param p3, p4  the opposite vertices, m
/// @return        d, sinPhi, q1..q4, valid
BendingGradients bendingGradients(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4);

/// Exercise 5.2 — projection of the bending constraint (Projektion des Biege-Constraint)
/// C = φ − φ0 with stiffness k, where \f$\varphi = \operatorname{atan2}(\sin\varphi,\ d) = \arccos(d)\f$
/// (sin φ and d from exercise 5.1).
///
/// Requirements (derive the corrections with the general PBD projection and the chain rule; the task
/// sheet's check of the slide's signs is part of it):
/// - the corrections are mass-weighted steps along \f$ -\nabla_{\vec p_i} C \f$, like the distance
///   constraint's, so \f$ \sum_i m_i\Delta\vec p_i = 0 \f$ and \f$ \sum_i \vec p_i\times m_i\Delta\vec p_i = 0 \f$
///   (no momentum, no angular momentum) and a pinned particle (w = 0) does not move;
/// - they reduce |C|: with k = 1, one projection removes more than 90 % of a small deviation (all of
///   it to first order); the stiffness k scales the corrections;
/// - near flat they stay accurate: compute with sin φ and atan2 as at the top of this file, not with
///   √(1 − d²) and arccos(d) as the slides write them.
/// Returns zero corrections, never NaN, when the stencil is not valid, when sin φ < 1e-6 (flat or
/// folded, i.e. 1 − d² < 1e-12: arccos is not differentiable there), when Σ w_j|q_j|² is zero (all
/// pinned) or when C = 0.
/// @param p1, p2, p3, p4  positions as in bendingGradients(), m
/// @param w1, w2, w3, w4  inverse masses, 1/kg
/// @param phi0            rest angle φ0, rad
/// @param k               stiffness in [0, 1]
/// @return                Δp1..Δp4, m
BendingCorrection projectBendingConstraint(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4,
                                           double w1, double w2, double w3, double w4, double phi0, double k);

/// Exercise 5.3 — the stencil topology: every interior edge of the triangle mesh (an edge shared
/// by exactly two triangles) gives one stencil (i1, i2 = the edge, i3, i4 = the vertices opposite it
/// in the two triangles) with the rest angle \f$\varphi_0 = \operatorname{atan2}(\sin\varphi,\ d)\f$ (= arccos d)
/// of the positions x, computed as in exercise 5.2.
/// Boundary edges (one triangle) give none. Degenerate rest shape (not valid): φ0 = π.
/// @param triangles  triangles as particle index triples
/// @param x          rest positions, 3 x N, m
/// @return           one stencil per interior edge (any order)
std::vector<BendingStencil> bendingStencils(const std::vector<Eigen::Vector3i>& triangles, const Matrix3X& x);

}  // namespace clothlab
