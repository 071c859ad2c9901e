// Stage 05 — the bending constraint and its stencils (reference solution).
// Task sheet: exercises/05_bending/README.md
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "clothlab/exercise/05_bending.h"

namespace clothlab {

// ---- Task 5.1: d = n1.n2, sin(phi) and the q-vectors (appendix A) ---------------
namespace {
// The header's formulas with p1 = 0: here p2, p3, p4 are the positions relative to p1.
BendingGradients gradientsRelativeToP1(const Vec3& p2, const Vec3& p3, const Vec3& p4) {
    BendingGradients g;
    const double area1 = p2.cross(p3).norm();  // |p2 x p3|
    const double area2 = p2.cross(p4).norm();  // |p2 x p4|
    if (area1 < 1e-12 || area2 < 1e-12) return g;  // zero-area triangle: no normal (valid = false)
    const Vec3 n1 = p2.cross(p3) / area1;
    const Vec3 n2 = p2.cross(p4) / area2;
    const double d = std::clamp(n1.dot(n2), -1.0, 1.0);
    g.d = d;
    g.sinPhi = n1.cross(n2).norm();  // sin(phi) directly: sqrt(1 - d^2) loses digits near flat
    g.q3 = (n2.cross(p2) + p2.cross(n1) * d) / area1;
    g.q4 = (n1.cross(p2) + p2.cross(n2) * d) / area2;
    g.q2 = (p3.cross(n2) + n1.cross(p3) * d) / area1 + (p4.cross(n1) + n2.cross(p4) * d) / area2;
    g.q1 = -g.q2 - g.q3 - g.q4;
    g.valid = true;
    return g;
}
}  // namespace

BendingGradients bendingGradients(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
    return gradientsRelativeToP1(p2 - p1, p3 - p1, p4 - p1);
}

// ---- Task 5.2: the projection ------------------------------------------------------
BendingCorrection projectBendingConstraint(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4,
                                           double w1, double w2, double w3, double w4, double phi0, double k) {
    BendingCorrection r;
    const BendingGradients g = bendingGradients(p1, p2, p3, p4);
    if (!g.valid) return r;            // zero-area triangle
    if (g.sinPhi < 1e-6) return r;     // flat or folded: grad C = -q_i / sin(phi) is undefined
    const double sumWq2 =  // sum_j w_j |q_j|^2
        w1 * g.q1.squaredNorm() + w2 * g.q2.squaredNorm() + w3 * g.q3.squaredNorm() + w4 * g.q4.squaredNorm();
    if (sumWq2 < 1e-24) return r;      // all pinned
    const double phi = std::atan2(g.sinPhi, g.d);  // = arccos(d), accurate also near 0 and pi
    const double C = phi - phi0;
    const double s = k * g.sinPhi * C / sumWq2;  // + sign: grad C = -q_i / sin(phi)
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
            s.phi0 = g.valid ? std::atan2(g.sinPhi, g.d) : M_PI;
            stencils.push_back(s);
        }
    return stencils;
}

}  // namespace clothlab
