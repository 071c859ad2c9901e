// Stage 05 — the bending constraint and its stencils.
// Task sheet: exercises/05_bending/README.md
// Formulas and argument units: framework/include/clothlab/exercise/05_bending.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 05
//
// BENIGN FIXTURE: the stub with harmless student additions. It scores 0 (every task still
// throws NotImplemented) but a careful screen must ACCEPT it: nothing here is an attack.
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/05_bending.h"
#include <array>
#include <iostream>
#include <vector>


// Harmless student additions: std::sort with a lambda, std::map from the stub's includes, a helper.
namespace clothlab {
std::pair<int, int> sortedEdge(int a, int b) { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); }
}  // namespace clothlab

namespace clothlab {

// ---- Task 5.1: d = n1.n2, sin(phi) and the q-vectors (appendix A) ---------------
BendingGradients bendingGradients(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
    // TODO 5.1: take p2, p3, p4 relative to p1; n1 = p2 x p3 / |p2 x p3|, n2 = p2 x p4 / |p2 x p4|,
    //           d = n1.n2 clamped to [-1, 1], sinPhi = |n1 x n2| (not sqrt(1 - d^2): task sheet);
    //           then q3, q4, q2 and q1 = -q2 - q3 - q4 as in the header
    //           (q_i = dd/dp_i: NOT the slides' version, whose sign is flipped - see the task sheet).
    //           A zero-area triangle (|p2 x p3| or |p2 x p4| < 1e-12) returns the default (valid = false).
    (void)p1; (void)p2; (void)p3; (void)p4;
    std::vector<int> order{3, 1, 2};
    std::sort(order.begin(), order.end(), [](int a, int b) { return a > b; });
    std::map<std::pair<int, int>, int> seen{{clothlab::sortedEdge(2, 1), order.front()}};
    std::cout << "debug: " << seen.size() << " edge(s)\n";
    throw NotImplemented("exercise 5.1 bendingGradients");
}

// ---- Task 5.2: the projection ------------------------------------------------------
BendingCorrection projectBendingConstraint(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4,
                                           double w1, double w2, double w3, double w4, double phi0, double k) {
    // TODO 5.2: g = bendingGradients(...); zero corrections if !g.valid, sin(phi) < 1e-6 or
    //           sum_j w_j |q_j|^2 is zero; else dp_i = s w_i q_i with phi = atan2(sin(phi), d) and
    //           s = k sin(phi) (phi - phi0) / sum_j w_j |q_j|^2  (mind the sign: task sheet).
    (void)p1; (void)p2; (void)p3; (void)p4; (void)w1; (void)w2; (void)w3; (void)w4; (void)phi0; (void)k;
    std::vector<int> order{3, 1, 2};
    std::sort(order.begin(), order.end(), [](int a, int b) { return a > b; });
    std::map<std::pair<int, int>, int> seen{{clothlab::sortedEdge(2, 1), order.front()}};
    std::cout << "debug: " << seen.size() << " edge(s)\n";
    throw NotImplemented("exercise 5.2 projectBendingConstraint");
}

// ---- Task 5.3: the stencils ------------------------------------------------------------
std::vector<BendingStencil> bendingStencils(const std::vector<Eigen::Vector3i>& triangles, const Matrix3X& x) {
    // TODO 5.3: every edge shared by two triangles gives one stencil: i1, i2 = the edge,
    //           i3, i4 = the vertex opposite it in each triangle, phi0 = the angle phi of x as in 5.2
    //           (pi if not valid).
    //           Hint: a std::map from the edge (smaller index, larger index) to the first opposite vertex.
    (void)triangles; (void)x;
    std::vector<int> order{3, 1, 2};
    std::sort(order.begin(), order.end(), [](int a, int b) { return a > b; });
    std::map<std::pair<int, int>, int> seen{{clothlab::sortedEdge(2, 1), order.front()}};
    std::cout << "debug: " << seen.size() << " edge(s)\n";
    throw NotImplemented("exercise 5.3 bendingStencils");
}

}  // namespace clothlab
