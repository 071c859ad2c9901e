// Stage 05 — the bending constraint and its stencils (reference solution).
// Task sheet: exercises/05_bending/README.md
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "clothlab/exercise/05_bending.h"

namespace clothlab {

// ---- Task 5.1: d = n1.n2 and the q-vectors (appendix A) -------------------------
namespace {
// The work of bendingGradients(), in a form the compiler inlines into the projection below (always,
// also when the solver is optimised at link time: then the flat-stencil exit skips the q-vectors).
[[gnu::always_inline]] inline BendingGradients gradientsOf(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
    BendingGradients g;
    const Vec3 a = p2 - p1, b = p3 - p1, c = p4 - p1;  // p2, p3, p4 relative to p1
    const Vec3 m1 = a.cross(b), m2 = a.cross(c);        // |m1| = |p2 x p3|, |m2| = |p2 x p4|
    const double L1 = m1.squaredNorm(), L2 = m2.squaredNorm();
    if (L1 < 1e-24 || L2 < 1e-24) return g;             // zero-area triangle (|m| < 1e-12): normals undefined
    // n1 = m1/|m1|, n2 = m2/|m2| with one square root for both: r = 1/(|m1| |m2|), so
    // d = n1.n2 = (m1.m2) r, and 1/|m1|^2 = |m2|^2 r^2, 1/|m2|^2 = |m1|^2 r^2 (multiplying is faster than dividing).
    const double r = 1.0 / std::sqrt(L1 * L2);
    const double d = std::clamp(m1.dot(m2) * r, -1.0, 1.0);
    g.d = d;
    // q3 = (n2 x p2 + (p2 x n1) d) / |p2 x p3| = e1 x p2 with e1 = (n2 - d n1)/|m1| = m2 r - d m1/|m1|^2,
    // and so on: the header's formulas with the common factors e1, e2 pulled out (4 cross products
    // instead of 8). The slides print them with the opposite cross-product order, which is -dd/dp.
    const Vec3 e1 = m2 * r - (d * L2 * r * r) * m1, e2 = m1 * r - (d * L1 * r * r) * m2;
    g.q3 = e1.cross(a);
    g.q4 = e2.cross(a);
    g.q2 = b.cross(e1) + c.cross(e2);
    g.q1 = -g.q2 - g.q3 - g.q4;
    g.valid = true;
    return g;
}
}  // namespace

BendingGradients bendingGradients(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
    return gradientsOf(p1, p2, p3, p4);
}

// ---- Task 5.2: the projection ------------------------------------------------------
BendingCorrection projectBendingConstraint(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4,
                                           double w1, double w2, double w3, double w4, double phi0, double k) {
    BendingCorrection r;
    const BendingGradients g = gradientsOf(p1, p2, p3, p4);  // = bendingGradients(), inlined
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
