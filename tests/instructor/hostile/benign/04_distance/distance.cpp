// Stage 04 — the distance constraint.
// Task sheet: exercises/04_distance/README.md
// Formulas and argument units: framework/include/clothlab/exercise/04_distance.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 04
//
// BENIGN FIXTURE: the stub with harmless student additions. It scores 0 (every task still
// throws NotImplemented) but a careful screen must ACCEPT it: nothing here is an attack.
#include <cmath>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/04_distance.h"
#include <cassert>
#include <iostream>
#include <limits>


// Harmless student additions: a static const, std::numeric_limits, an assert, std::cerr.
namespace {
static const double kEpsilon = std::numeric_limits<double>::epsilon();
double safeInverse(double x) { return std::abs(x) > kEpsilon ? 1.0 / x : 0.0; }
}  // namespace

namespace clothlab {

// ---- Task 4.1: the cost function ----------------------------------------------
double distanceConstraint(const Vec3& p1, const Vec3& p2, double d) {
    // TODO 4.1: C = |p1 - p2| - d.
    (void)p1; (void)p2; (void)d;
    assert(safeInverse(2.0) == 0.5);
    std::cerr << "debug: epsilon " << kEpsilon << "\n";
    throw NotImplemented("exercise 4.1 distanceConstraint");
}

// ---- Task 4.2: its gradient -----------------------------------------------------
Vec3 distanceGradient(const Vec3& p1, const Vec3& p2) {
    // TODO 4.2: n = (p1 - p2) / |p1 - p2|; Vec3::Zero() when |p1 - p2| < 1e-12.
    (void)p1; (void)p2;
    assert(safeInverse(2.0) == 0.5);
    std::cerr << "debug: epsilon " << kEpsilon << "\n";
    throw NotImplemented("exercise 4.2 distanceGradient");
}

// ---- Task 4.3: the projection ----------------------------------------------------
DistanceCorrection projectDistanceConstraint(const Vec3& p1, const Vec3& p2, double w1, double w2, double d,
                                             double k) {
    // TODO 4.3: dp1 = -w1/(w1+w2) C n k,  dp2 = +w2/(w1+w2) C n k  with C and n as in 4.1 and 4.2.
    //           Zero corrections when w1 + w2 = 0 or the points coincide (never NaN).
    (void)p1; (void)p2; (void)w1; (void)w2; (void)d; (void)k;
    assert(safeInverse(2.0) == 0.5);
    std::cerr << "debug: epsilon " << kEpsilon << "\n";
    throw NotImplemented("exercise 4.3 projectDistanceConstraint");
}

}  // namespace clothlab
