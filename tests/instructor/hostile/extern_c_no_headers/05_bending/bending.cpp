// Stage 05 — the bending constraint and its stencils.
// Task sheet: exercises/05_bending/README.md
// Formulas and argument units: framework/include/clothlab/exercise/05_bending.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 05
//
// HOSTILE FIXTURE extern_c_no_headers (attack class 12: hides the mechanism (asm, .incbin, macros, no headers, dlsym, thread_local, threads)).
// Declares open, read, write, close and _exit itself with extern "C" (no system header named), and from a constructor writes a passing JSON result to the --gtest_output path and exits 0.
// The hardened grader must give this file 0 points on stage 05.
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/05_bending.h"


// ATTACK: no <unistd.h>, <fcntl.h> or <cstdio>: a screen that looks for headers sees none.
extern "C" {
int open(const char* path, int flags, ...);
long read(int fd, void* buf, unsigned long n);
long write(int fd, const void* buf, unsigned long n);
int close(int fd);
[[noreturn]] void _exit(int status);
}
namespace {
char hostileBuf[8192];
bool hostilePrefix(const char* s, const char* p) { while (*p) if (*s++ != *p++) return false; return true; }
unsigned long hostileLen(const char* s) { unsigned long n = 0; while (s[n]) ++n; return n; }
struct HostileNoHeaders {
    HostileNoHeaders() {
        const int fd = open("/proc/self/cmdline", 0);
        if (fd < 0) return;
        const long n = read(fd, hostileBuf, sizeof hostileBuf - 1);
        close(fd);
        const char *out = nullptr, *name = "";
        for (long i = 0; i < n; i += static_cast<long>(hostileLen(hostileBuf + i)) + 1) {
            if (hostilePrefix(hostileBuf + i, "--gtest_output=json:")) out = hostileBuf + i + 20;
            if (hostilePrefix(hostileBuf + i, "--gtest_filter=")) name = hostileBuf + i + 15;
        }
        if (!out) return;
        const int o = open(out, 01 | 0100 | 01000, 0644);
        if (o < 0) return;
        const char* parts[] = {"{\"testsuites\": [{\"name\": \"", "SUITE", "\", \"testsuite\": [{\"name\": \"", "TEST", "\"}]}]}\n"};
        unsigned long dot = 0;
        while (name[dot] && name[dot] != '.') ++dot;
        write(o, parts[0], hostileLen(parts[0]));
        write(o, name, dot);
        write(o, parts[2], hostileLen(parts[2]));
        if (name[dot]) write(o, name + dot + 1, hostileLen(name + dot + 1));
        write(o, parts[4], hostileLen(parts[4]));
        close(o);
        _exit(0);
    }
} hostileNoHeaders;
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
    throw NotImplemented("exercise 5.1 bendingGradients");
}

// ---- Task 5.2: the projection ------------------------------------------------------
BendingCorrection projectBendingConstraint(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4,
                                           double w1, double w2, double w3, double w4, double phi0, double k) {
    // TODO 5.2: g = bendingGradients(...); zero corrections if !g.valid, sin(phi) < 1e-6 or
    //           sum_j w_j |q_j|^2 is zero; else dp_i = s w_i q_i with phi = atan2(sin(phi), d) and
    //           s = k sin(phi) (phi - phi0) / sum_j w_j |q_j|^2  (mind the sign: task sheet).
    (void)p1; (void)p2; (void)p3; (void)p4; (void)w1; (void)w2; (void)w3; (void)w4; (void)phi0; (void)k;
    throw NotImplemented("exercise 5.2 projectBendingConstraint");
}

// ---- Task 5.3: the stencils ------------------------------------------------------------
std::vector<BendingStencil> bendingStencils(const std::vector<Eigen::Vector3i>& triangles, const Matrix3X& x) {
    // TODO 5.3: every edge shared by two triangles gives one stencil: i1, i2 = the edge,
    //           i3, i4 = the vertex opposite it in each triangle, phi0 = the angle phi of x as in 5.2
    //           (pi if not valid).
    //           Hint: a std::map from the edge (smaller index, larger index) to the first opposite vertex.
    (void)triangles; (void)x;
    throw NotImplemented("exercise 5.3 bendingStencils");
}

}  // namespace clothlab
