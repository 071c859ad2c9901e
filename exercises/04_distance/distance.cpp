// Stage 04 — the distance constraint.
// Task sheet: exercises/04_distance/README.md
// Contract (arguments, units, requirements): framework/include/clothlab/exercise/04_distance.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 04
// Stuck? `./lab hint 4.1` (or 4.2, ...) asks a question and names the slide; add 2 for one sub-step, 3 for the formula.
#include <cmath>
#include <vector>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/04_distance.h"

namespace clothlab {

// ---- Task 4.1: the cost function ----------------------------------------------
double distanceConstraint(const Vec3& p1, const Vec3& p2, double d) {
    // TODO 4.1: the cost function of the distance constraint (task sheet 4.1; contract in the header)
    (void)p1; (void)p2; (void)d;
    throw NotImplemented("exercise 4.1 distanceConstraint");
}

// ---- Task 4.2: its gradient -----------------------------------------------------
Vec3 distanceGradient(const Vec3& p1, const Vec3& p2) {
    // TODO 4.2: the gradient of the distance constraint (task sheet 4.2; contract in the header)
    (void)p1; (void)p2;
    throw NotImplemented("exercise 4.2 distanceGradient");
}

// ---- Task 4.3: the projection ----------------------------------------------------
DistanceCorrection projectDistanceConstraint(const Vec3& p1, const Vec3& p2, double w1, double w2, double d,
                                             double k) {
    // TODO 4.3: the projection of the distance constraint (task sheet 4.3; contract in the header)
    (void)p1; (void)p2; (void)w1; (void)w2; (void)d; (void)k;
    throw NotImplemented("exercise 4.3 projectDistanceConstraint");
}

// ---- Bonus 4.4: long-range attachments (optional, beyond the slides) ---------------------------
std::vector<int> tetherAnchors(const Matrix3X& rest, const VectorX& w) {
    // TODO 4.4: bonus, the nearest pinned particle of every free one (task sheet 4.4; contract in the header)
    (void)rest; (void)w;
    throw NotImplemented("exercise 4.4 tetherAnchors (bonus)");
}

Vec3 projectTether(const Vec3& p, const Vec3& anchor, double L) {
    // TODO 4.4: bonus, the one-sided tether projection (task sheet 4.4; contract in the header)
    (void)p; (void)anchor; (void)L;
    throw NotImplemented("exercise 4.4 projectTether (bonus)");
}

}  // namespace clothlab
