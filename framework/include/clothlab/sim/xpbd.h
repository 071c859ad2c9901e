/// @file xpbd.h
/// @brief XPBD (Macklin, Müller, Chentanez 2016): compliant distance and bending constraints with a
/// Lagrange multiplier λ per constraint, so the stiffness no longer depends on the iteration count.
///
/// For a constraint C with gradients ∇_i C, compliance α (inverse stiffness) and time step Δt:
/// \f[ \tilde\alpha = \frac{\alpha}{\Delta t^2},\qquad
///     \Delta\lambda = \frac{-C - \tilde\alpha\,\lambda}{\sum_i w_i|\nabla_i C|^2 + \tilde\alpha},\qquad
///     \lambda \leftarrow \lambda + \Delta\lambda,\qquad \Delta\vec p_i = w_i\,\nabla_i C\,\Delta\lambda \f]
/// λ starts at 0 in every (sub)step. α = 0 gives a hard constraint (PBD with k = 1).
/// The corrections are the stage functions' (exercise 4.3, exercise 5.2) at k = 1, scaled by xpbdScale().
#pragma once
#include "clothlab/exercise/04_distance.h"
#include "clothlab/exercise/05_bending.h"

namespace clothlab {

/// The factor f by which XPBD scales a constraint's PBD correction \f$ \Delta\vec p_i^{PBD} \f$ (the stage
/// function at k = 1, which moves each particle along \f$ w_i\nabla_i C \f$): XPBD moves along the same
/// vectors, \f$ \Delta\vec p_i = w_i\nabla_i C\,\Delta\lambda = f\,\Delta\vec p_i^{PBD} \f$, and with
/// \f$ S = \sum_j w_j|\nabla_j C|^2 \f$ and \f$ \sigma = \sum_i |\Delta\vec p_i^{PBD}|^2/w_i = C^2/S \f$ (over the free particles),
/// \f[ \Delta\lambda = \frac{-C - \tilde\alpha\lambda}{S + \tilde\alpha} = -\frac{(C + \tilde\alpha\lambda)\,\sigma}{C^2 + \tilde\alpha\sigma},
///     \qquad f = \frac{(C + \tilde\alpha\lambda)\,C}{C^2 + \tilde\alpha\sigma}. \f]
/// λ is updated by Δλ. No correction (f = 0, λ unchanged) where the PBD correction is zero (σ = 0:
/// degenerate, all pinned, or C = 0).
/// @param C           the constraint's value (m for distance, rad for bending)
/// @param sigma       σ = Σ_i |Δp_i^PBD|² / w_i over the particles with w_i > 0
/// @param alphaTilde  α / Δt²
/// @param lambda      the constraint's multiplier λ, updated
/// @return            f
double xpbdScale(double C, double sigma, double alphaTilde, double& lambda);

/// One XPBD projection of the distance constraint C = |p1 − p2| − d, built on exercise 4.3 (its
/// correction at k = 1, scaled by xpbdScale()) and exercise 4.1 (C).
/// @param p1, p2       end points, m
/// @param w1, w2       inverse masses, 1/kg
/// @param d            rest length, m
/// @param alphaTilde   α / Δt², kg⁻¹ (α in m/N)
/// @param lambda       the constraint's multiplier λ (kg m), updated
/// @return             Δp1, Δp2, m (zero where exercise 4.3 gives none: both pinned, coincident points, C = 0)
DistanceCorrection projectDistanceXpbd(const Vec3& p1, const Vec3& p2, double w1, double w2, double d,
                                       double alphaTilde, double& lambda);

/// The dihedral angle of a stencil from exercise 5.1's output: \f$ \varphi = \operatorname{atan2}(\sin\varphi, d) \f$
/// (accurate at every angle, unlike arccos d near flat), π for a degenerate stencil (valid = false).
/// @param g  d = cos φ and sin φ of the stencil
/// @return   φ in [0, π], rad
double bendingAngle(const BendingGradients& g);

/// The dihedral angle of a stencil straight from its positions, without the q-vectors: with
/// \f$\vec a=\vec p_2-\vec p_1\f$, \f$\vec b=\vec p_3-\vec p_1\f$, \f$\vec c=\vec p_4-\vec p_1\f$ the normals are
/// \f$\vec a\times\vec b\f$ and \f$\vec a\times\vec c\f$, and since \f$(\vec a\times\vec b)\times(\vec a\times\vec c)
/// = \vec a\,(\vec a\cdot(\vec b\times\vec c))\f$,
/// \f[ \varphi = \operatorname{atan2}\big(|\vec a|\,|\vec a\cdot(\vec b\times\vec c)|,\ (\vec a\times\vec b)\cdot(\vec a\times\vec c)\big), \f]
/// the angle bendingAngle() gives for a valid stencil (atan2 does not care for the scale of its arguments).
/// @param p1, p2, p3, p4  positions as in bendingGradients(), m
/// @return                φ in [0, π], rad (π for a flat stencil; meaningless for a zero-area triangle)
double dihedralAngle(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4);

/// One XPBD projection of the bending constraint C = φ − φ0, built on exercise 5.2 (its correction
/// at k = 1, scaled by xpbdScale()). Where exercise 5.2 gives no correction (degenerate stencil, all
/// pinned, C = 0) this gives none either.
/// @param p1, p2, p3, p4  positions as in bendingGradients(), m
/// @param w1, w2, w3, w4  inverse masses, 1/kg
/// @param phi0            rest angle, rad
/// @param alphaTilde      α / Δt² (α in 1/(N m)), the compliance of the angle
/// @param lambda          the constraint's multiplier λ, updated
/// @return                Δp1..Δp4, m
BendingCorrection projectBendingXpbd(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4, double w1,
                                     double w2, double w3, double w4, double phi0, double alphaTilde, double& lambda);

}  // namespace clothlab
