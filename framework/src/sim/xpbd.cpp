#include "clothlab/sim/xpbd.h"

#include <cmath>

namespace clothlab {

double bendingAngle(const BendingGradients& g) {
    if (!g.valid) return M_PI;
    return std::atan2(g.sinPhi, g.d);
}

double dihedralAngle(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
    const Vec3 a = p2 - p1, b = p3 - p1, c = p4 - p1;
    // (a × b) × (a × c) = a (a · (b × c)): its length is |a| |a · (b × c)|
    return std::atan2(a.norm() * std::fabs(a.dot(b.cross(c))), a.cross(b).dot(a.cross(c)));
}

BendingCorrection projectBendingXpbd(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4, double w1,
                                     double w2, double w3, double w4, double phi0, double alphaTilde, double& lambda) {
    // Exercise 5.2 with k = 1 gives the PBD correction Δp_i = −(C/S) w_i ∇_i C, S = Σ_j w_j|∇_j C|².
    // XPBD moves along the same vectors, Δp_i = w_i ∇_i C Δλ = f Δp_i^PBD with f = −(S/C) Δλ; S follows
    // from the PBD correction itself, Σ_i |Δp_i^PBD|²/w_i = C²/S.
    const BendingCorrection pbd = projectBendingConstraint(p1, p2, p3, p4, w1, w2, w3, w4, phi0, 1.0);
    const double C = dihedralAngle(p1, p2, p3, p4) - phi0;  // the constraint, C = φ − φ0
    // Σ_i |Δp_i|² / w_i over the free particles (the four divisions do not wait for each other)
    const double sum = (w1 > 0.0 ? pbd.dp1.squaredNorm() / w1 : 0.0) + (w2 > 0.0 ? pbd.dp2.squaredNorm() / w2 : 0.0) +
                       (w3 > 0.0 ? pbd.dp3.squaredNorm() / w3 : 0.0) + (w4 > 0.0 ? pbd.dp4.squaredNorm() / w4 : 0.0);
    // With S = C²/sum: Δλ = (−C − α̃λ)/(S + α̃) = −(C + α̃λ) sum g and f = (C + α̃λ) C g, g = 1/(C² + α̃ sum).
    const double denom = C * C + alphaTilde * sum;
    if (!(sum > 0.0) || !(denom > 0.0)) return {};  // no correction: degenerate stencil, all pinned, or at rest
    const double g = 1.0 / denom, Cl = C + alphaTilde * lambda;
    lambda -= Cl * sum * g;
    const double f = Cl * C * g;
    BendingCorrection r;
    r.dp1 = f * pbd.dp1;
    r.dp2 = f * pbd.dp2;
    r.dp3 = f * pbd.dp3;
    r.dp4 = f * pbd.dp4;
    return r;
}

}  // namespace clothlab
