#include "clothlab/sim/xpbd.h"

#include <cmath>
#include <utility>

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
    // XPBD moves along the same vectors, Δp_i = w_i ∇_i C Δλ = −(S/C) Δλ Δp_i; S follows from the
    // PBD correction itself, Σ_i |Δp_i|²/w_i = C²/S.
    const BendingCorrection pbd = projectBendingConstraint(p1, p2, p3, p4, w1, w2, w3, w4, phi0, 1.0);
    double sum = 0.0;  // Σ_i |Δp_i|² / w_i over the free particles
    const std::pair<const Vec3*, double> parts[] = {{&pbd.dp1, w1}, {&pbd.dp2, w2}, {&pbd.dp3, w3}, {&pbd.dp4, w4}};
    for (const auto& [dp, w] : parts)
        if (w > 0.0) sum += dp->squaredNorm() / w;
    if (!(sum > 0.0)) return {};  // no correction: degenerate stencil, all pinned, or exactly at rest (C = 0)
    const double C = dihedralAngle(p1, p2, p3, p4) - phi0;  // the constraint, C = φ − φ0
    const double S = C * C / sum;
    const double dl = (-C - alphaTilde * lambda) / (S + alphaTilde);
    lambda += dl;
    const double f = -(S / C) * dl;
    BendingCorrection r;
    r.dp1 = f * pbd.dp1;
    r.dp2 = f * pbd.dp2;
    r.dp3 = f * pbd.dp3;
    r.dp4 = f * pbd.dp4;
    return r;
}

}  // namespace clothlab
