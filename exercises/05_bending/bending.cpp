// Stage 05 — the bending constraint and its stencils.
// Task sheet: exercises/05_bending/README.md
// Contract (arguments, units, requirements): framework/include/clothlab/exercise/05_bending.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 05
// Stuck? `./lab hint 5.1` (or 5.2, ...) asks a question and names the slide; add 2 for one sub-step, 3 for the formula.
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/05_bending.h"

namespace clothlab {

// ---- Task 5.1: d = n1.n2, sin(phi) and the q-vectors (appendix A) ---------------
BendingGradients bendingGradients(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
    // TODO 5.1: d, sin phi and the q-vectors (task sheet 5.1; contract in the header)
    (void)p1; (void)p2; (void)p3; (void)p4;
    throw NotImplemented("exercise 5.1 bendingGradients");
}

// ---- Task 5.2: the projection ------------------------------------------------------
BendingCorrection projectBendingConstraint(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4,
                                           double w1, double w2, double w3, double w4, double phi0, double k) {
    // TODO 5.2: the projection of the bending constraint (task sheet 5.2; contract in the header)
    (void)p1; (void)p2; (void)p3; (void)p4; (void)w1; (void)w2; (void)w3; (void)w4; (void)phi0; (void)k;
    throw NotImplemented("exercise 5.2 projectBendingConstraint");
}

// ---- Task 5.3: the stencils ------------------------------------------------------------
std::vector<BendingStencil> bendingStencils(const std::vector<Eigen::Vector3i>& triangles, const Matrix3X& x) {
    // TODO 5.3: the bending stencils of a triangle mesh (task sheet 5.3; contract in the header)
    (void)triangles; (void)x;
    throw NotImplemented("exercise 5.3 bendingStencils");
}

}  // namespace clothlab
