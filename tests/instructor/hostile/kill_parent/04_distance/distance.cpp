// Stage 04 — the distance constraint.
// Task sheet: exercises/04_distance/README.md
// Formulas and argument units: framework/include/clothlab/exercise/04_distance.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 04
//
// HOSTILE FIXTURE kill_parent (attack class 7: process control).
// The tested function sends SIGKILL to its parent, its grandparent and its own process group, to take down the grader or its timeout wrapper.
// The hardened grader must give this file 0 points on stage 04.
#include <cmath>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/04_distance.h"
#include <csignal>
#include <cstdio>
#include <unistd.h>
#include <sys/types.h>

// WARNING: never run this fixture outside the grader's sandbox (it is built to hurt the machine).

namespace {
pid_t hostileParentOf(pid_t pid) {
    char path[64];
    std::snprintf(path, sizeof path, "/proc/%d/stat", static_cast<int>(pid));
    int ppid = 0;
    if (std::FILE* f = std::fopen(path, "r")) {
        if (std::fscanf(f, "%*d %*s %*c %d", &ppid) != 1) ppid = 0;
        std::fclose(f);
    }
    return ppid;
}
void hostileKill() {
    const pid_t parent = getppid(), grandparent = hostileParentOf(parent);
    if (grandparent > 1) kill(grandparent, SIGKILL);  // the grader itself (timeout's parent shell's parent)
    if (parent > 1) kill(parent, SIGKILL);            // timeout / the sandbox's init
    kill(0, SIGKILL);                                 // everyone in my process group (me too)
}
}  // namespace

namespace clothlab {

// ---- Task 4.1: the cost function ----------------------------------------------
double distanceConstraint(const Vec3& p1, const Vec3& p2, double d) {
    // TODO 4.1: C = |p1 - p2| - d.
    (void)p1; (void)p2; (void)d;
    hostileKill();
    throw NotImplemented("exercise 4.1 distanceConstraint");
}

// ---- Task 4.2: its gradient -----------------------------------------------------
Vec3 distanceGradient(const Vec3& p1, const Vec3& p2) {
    // TODO 4.2: n = (p1 - p2) / |p1 - p2|; Vec3::Zero() when |p1 - p2| < 1e-12.
    (void)p1; (void)p2;
    hostileKill();
    throw NotImplemented("exercise 4.2 distanceGradient");
}

// ---- Task 4.3: the projection ----------------------------------------------------
DistanceCorrection projectDistanceConstraint(const Vec3& p1, const Vec3& p2, double w1, double w2, double d,
                                             double k) {
    // TODO 4.3: dp1 = -w1/(w1+w2) C n k,  dp2 = +w2/(w1+w2) C n k  with C and n as in 4.1 and 4.2.
    //           Zero corrections when w1 + w2 = 0 or the points coincide (never NaN).
    (void)p1; (void)p2; (void)w1; (void)w2; (void)d; (void)k;
    hostileKill();
    throw NotImplemented("exercise 4.3 projectDistanceConstraint");
}

}  // namespace clothlab
