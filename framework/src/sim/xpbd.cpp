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

double xpbdScale(double C, double sigma, double alphaTilde, double& lambda) {
    const double denom = C * C + alphaTilde * sigma;
    if (!(sigma > 0.0) || !(denom > 0.0)) return 0.0;
    const double g = 1.0 / denom, Cl = C + alphaTilde * lambda;
    lambda -= Cl * sigma * g;
    return Cl * C * g;
}

/// |Δp|² / w of one particle's PBD correction, 0 for a pinned particle (w = 0).
static double weightedSquare(const Vec3& dp, double w) { return w > 0.0 ? dp.squaredNorm() / w : 0.0; }

DistanceCorrection projectDistanceXpbd(const Vec3& p1, const Vec3& p2, double w1, double w2, double d,
                                       double alphaTilde, double& lambda) {
    const DistanceCorrection pbd = projectDistanceConstraint(p1, p2, w1, w2, d, 1.0);
    const double sigma = weightedSquare(pbd.dp1, w1) + weightedSquare(pbd.dp2, w2);
    const double f = xpbdScale(distanceConstraint(p1, p2, d), sigma, alphaTilde, lambda);
    return {f * pbd.dp1, f * pbd.dp2};
}

BendingCorrection projectBendingXpbd(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4, double w1,
                                     double w2, double w3, double w4, double phi0, double alphaTilde, double& lambda) {
    const BendingCorrection pbd = projectBendingConstraint(p1, p2, p3, p4, w1, w2, w3, w4, phi0, 1.0);
    const double sigma = weightedSquare(pbd.dp1, w1) + weightedSquare(pbd.dp2, w2) + weightedSquare(pbd.dp3, w3) +
                         weightedSquare(pbd.dp4, w4);
    const double f = xpbdScale(dihedralAngle(p1, p2, p3, p4) - phi0, sigma, alphaTilde, lambda);  // C = φ − φ0
    BendingCorrection r;
    r.dp1 = f * pbd.dp1;
    r.dp2 = f * pbd.dp2;
    r.dp3 = f * pbd.dp3;
    r.dp4 = f * pbd.dp4;
    return r;
}

}  // namespace clothlab
