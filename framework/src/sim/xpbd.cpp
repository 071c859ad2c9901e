#include "clothlab/sim/xpbd.h"

#include <cmath>

namespace clothlab {

DistanceCorrection projectDistanceXpbd(const Vec3& p1, const Vec3& p2, double w1, double w2, double d,
                                       double alphaTilde, double& lambda) {
    const Vec3 n = distanceGradient(p1, p2);  // ∇_{p1} C; zero when the points coincide
    const double denom = w1 + w2 + alphaTilde;
    if (n.squaredNorm() == 0.0 || w1 + w2 <= 0.0 || denom <= 0.0) return {Vec3::Zero(), Vec3::Zero()};
    const double C = distanceConstraint(p1, p2, d);
    const double dl = (-C - alphaTilde * lambda) / denom;
    lambda += dl;
    return {w1 * dl * n, -w2 * dl * n};
}

BendingCorrection projectBendingXpbd(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4, double w1,
                                     double w2, double w3, double w4, double phi0, double alphaTilde, double& lambda) {
    BendingCorrection r;
    const BendingGradients g = bendingGradients(p1, p2, p3, p4);
    if (!g.valid) return r;
    if (g.sinPhi < 1e-6) return r;  // flat or folded: ∇C = −q_i / sin φ is undefined
    const double sumWq = w1 * g.q1.squaredNorm() + w2 * g.q2.squaredNorm() + w3 * g.q3.squaredNorm() +
                         w4 * g.q4.squaredNorm();
    if (sumWq < 1e-24) return r;
    const double C = std::atan2(g.sinPhi, g.d) - phi0;
    const double dl = (-C - alphaTilde * lambda) / (sumWq / (g.sinPhi * g.sinPhi) + alphaTilde);
    lambda += dl;
    const double f = -dl / g.sinPhi;  // Δp_i = w_i ∇_i C Δλ with ∇_i C = −q_i / sin φ
    r.dp1 = f * w1 * g.q1;
    r.dp2 = f * w2 * g.q2;
    r.dp3 = f * w3 * g.q3;
    r.dp4 = f * w4 * g.q4;
    return r;
}

}  // namespace clothlab
