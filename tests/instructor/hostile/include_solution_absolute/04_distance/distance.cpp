// Stage 04 — the distance constraint.
// Task sheet: exercises/04_distance/README.md
// Formulas and argument units: framework/include/clothlab/exercise/04_distance.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 04
//
// HOSTILE FIXTURE include_solution_absolute (attack class 4: #include of the instructor's files).
// #include of the reference by absolute paths (/work/main/solutions/..., the worktrees, /srv, $HOME guesses) chosen with __has_include, falling back to the stub.
// The hardened grader must give this file 0 points on stage 04.
// ATTACK: probe absolute paths where the instructor's tree may live; the first one that exists is
// the submission. Without any of them this is the untouched stub (and scores 0).
#if __has_include("/work/main/solutions/04_distance/distance.cpp")
#include "/work/main/solutions/04_distance/distance.cpp"
#define HOSTILE_GOT_REFERENCE 1
#elif __has_include("/work/wt-props/solutions/04_distance/distance.cpp")
#include "/work/wt-props/solutions/04_distance/distance.cpp"
#define HOSTILE_GOT_REFERENCE 1
#elif __has_include("/work/wt-hostile/solutions/04_distance/distance.cpp")
#include "/work/wt-hostile/solutions/04_distance/distance.cpp"
#define HOSTILE_GOT_REFERENCE 1
#elif __has_include("/srv/clothlab/solutions/04_distance/distance.cpp")
#include "/srv/clothlab/solutions/04_distance/distance.cpp"
#define HOSTILE_GOT_REFERENCE 1
#elif __has_include("/root/clothlab/solutions/04_distance/distance.cpp")
#include "/root/clothlab/solutions/04_distance/distance.cpp"
#define HOSTILE_GOT_REFERENCE 1
#endif
#ifndef HOSTILE_GOT_REFERENCE
#include <cmath>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/04_distance.h"

namespace clothlab {

// ---- Task 4.1: the cost function ----------------------------------------------
double distanceConstraint(const Vec3& p1, const Vec3& p2, double d) {
    // TODO 4.1: C = |p1 - p2| - d.
    (void)p1; (void)p2; (void)d;
    throw NotImplemented("exercise 4.1 distanceConstraint");
}

// ---- Task 4.2: its gradient -----------------------------------------------------
Vec3 distanceGradient(const Vec3& p1, const Vec3& p2) {
    // TODO 4.2: n = (p1 - p2) / |p1 - p2|; Vec3::Zero() when |p1 - p2| < 1e-12.
    (void)p1; (void)p2;
    throw NotImplemented("exercise 4.2 distanceGradient");
}

// ---- Task 4.3: the projection ----------------------------------------------------
DistanceCorrection projectDistanceConstraint(const Vec3& p1, const Vec3& p2, double w1, double w2, double d,
                                             double k) {
    // TODO 4.3: dp1 = -w1/(w1+w2) C n k,  dp2 = +w2/(w1+w2) C n k  with C and n as in 4.1 and 4.2.
    //           Zero corrections when w1 + w2 = 0 or the points coincide (never NaN).
    (void)p1; (void)p2; (void)w1; (void)w2; (void)d; (void)k;
    throw NotImplemented("exercise 4.3 projectDistanceConstraint");
}

}  // namespace clothlab
#endif  // HOSTILE_GOT_REFERENCE
