// Stage 05 — the bending constraint and its stencils (reference solution).
// Task sheet: exercises/05_bending/README.md
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "clothlab/exercise/05_bending.h"

namespace clothlab {

// ---- Task 5.1: d = n1.n2 and the q-vectors (appendix A) -------------------------
BendingGradients bendingGradients(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
    BendingGradients g;
    const Vec3 a = p2 - p1, b = p3 - p1, c = p4 - p1;  // p2, p3, p4 relative to p1
    const Vec3 m1 = a.cross(b), m2 = a.cross(c);
    const double l1 = m1.norm(), l2 = m2.norm();        // |p2 x p3|, |p2 x p4|
    if (l1 < 1e-12 || l2 < 1e-12) return g;             // zero-area triangle: normals undefined
    const double i1 = 1.0 / l1, i2 = 1.0 / l2;           // multiply by these instead of dividing (faster)
    const Vec3 n1 = m1 * i1, n2 = m2 * i2;
    const double d = std::clamp(n1.dot(n2), -1.0, 1.0);
    g.d = d;
    // q3 = (n2 x p2 + (p2 x n1) d) / |p2 x p3| = ((n2 - d n1) x p2) / |p2 x p3|, and so on: the header's
    // formulas with the common factors e1, e2 pulled out (4 cross products instead of 8).
    // The slides print them with the opposite cross-product order, which is -dd/dp (see the task sheet).
    const Vec3 e1 = (n2 - d * n1) * i1, e2 = (n1 - d * n2) * i2;
    g.q3 = e1.cross(a);
    g.q4 = e2.cross(a);
    g.q2 = b.cross(e1) + c.cross(e2);
    g.q1 = -g.q2 - g.q3 - g.q4;
    g.valid = true;
    return g;
}

// ---- Task 5.2: the projection ------------------------------------------------------
BendingCorrection projectBendingConstraint(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4,
                                           double w1, double w2, double w3, double w4, double phi0, double k) {
    BendingCorrection r;
    const BendingGradients g = bendingGradients(p1, p2, p3, p4);
    if (!g.valid) return r;
    const double s2 = 1.0 - g.d * g.d;
    if (s2 < 1e-12) return r;                          // flat or folded: arccos not differentiable
    const double denom = w1 * g.q1.squaredNorm() + w2 * g.q2.squaredNorm() + w3 * g.q3.squaredNorm() +
                         w4 * g.q4.squaredNorm();
    if (denom < 1e-24) return r;                       // all pinned
    const double f = k * std::sqrt(s2) / denom;        // (computed while acos runs)
    const double C = std::acos(g.d) - phi0;
    const double s = f * C;                            // + sign: dC/dp_i = -q_i / sqrt(1 - d^2)
    r.dp1 = s * w1 * g.q1;
    r.dp2 = s * w2 * g.q2;
    r.dp3 = s * w3 * g.q3;
    r.dp4 = s * w4 * g.q4;
    return r;
}

// ---- Task 5.3: the stencils ------------------------------------------------------------
std::vector<BendingStencil> bendingStencils(const std::vector<Eigen::Vector3i>& triangles, const Matrix3X& x) {
    // For every edge (smaller index first): the vertex opposite it in the first triangle seen.
    std::map<std::pair<int, int>, int> firstOpposite;
    std::vector<BendingStencil> stencils;
    for (const auto& t : triangles)
        for (int e = 0; e < 3; ++e) {
            const int a = t[e], b = t[(e + 1) % 3], opposite = t[(e + 2) % 3];
            const auto key = std::minmax(a, b);
            const auto it = firstOpposite.find(key);
            if (it == firstOpposite.end()) {
                firstOpposite.emplace(key, opposite);
                continue;
            }
            BendingStencil s;
            s.i1 = key.first;
            s.i2 = key.second;
            s.i3 = it->second;
            s.i4 = opposite;
            const BendingGradients g = bendingGradients(x.col(s.i1), x.col(s.i2), x.col(s.i3), x.col(s.i4));
            s.phi0 = g.valid ? std::acos(g.d) : M_PI;
            stencils.push_back(s);
        }
    return stencils;
}

}  // namespace clothlab
