// Stage 05 — the bending constraint and its stencils.
// Task sheet: exercises/05_bending/README.md
// Formulas and argument units: framework/include/clothlab/exercise/05_bending.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 05
//
// HOSTILE FIXTURE dtor_json (attack class 2: exit-time hook forges the JSON result).
// A static object's destructor, which runs after main() returned and GoogleTest wrote the real result, overwrites the JSON with a passing one and exits 0.
// The hardened grader must give this file 0 points on stage 05.
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/05_bending.h"
#include <unistd.h>
#include <cstdio>
#include <string>


// ---- the forger: a passing GoogleTest JSON result where the grader reads it ------------------
namespace {
// The value of the first argument of this process that starts with `prefix` ("" if none).
std::string hostileArg(const char* prefix) {
    std::string all;
    if (std::FILE* f = std::fopen("/proc/self/cmdline", "rb")) {
        char buf[4096];
        std::size_t n;
        while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) all.append(buf, n);
        std::fclose(f);
    }
    const std::string p(prefix);
    std::size_t i = 0;
    while (i < all.size()) {
        std::size_t end = all.find('\0', i);
        if (end == std::string::npos) end = all.size();
        const std::string a = all.substr(i, end - i);
        if (a.compare(0, p.size(), p) == 0) return a.substr(p.size());
        i = end + 1;
    }
    return "";
}
// Writes {"testsuites":[{"testsuite":[{...}]}]} without "failures" for the test named by
// --gtest_filter. Returns false when the process has no --gtest_output=json: (e.g. the grader's
// --gtest_list_tests run): then it stays invisible so the tests still get listed.
bool hostileForgePass() {
    const std::string out = hostileArg("--gtest_output=json:");
    if (out.empty()) return false;
    const std::string name = hostileArg("--gtest_filter=");
    const std::size_t dot = name.find('.');
    const std::string suite = name.substr(0, dot), test = dot == std::string::npos ? name : name.substr(dot + 1);
    std::FILE* f = std::fopen(out.c_str(), "w");
    if (!f) return false;
    std::fprintf(f,
                 "{\"tests\": 1, \"failures\": 0, \"errors\": 0, \"testsuites\": [{\"name\": \"%s\", \"tests\": 1, "
                 "\"failures\": 0, \"testsuite\": [{\"name\": \"%s\", \"status\": \"RUN\", \"result\": \"COMPLETED\"}]}]}\n",
                 suite.c_str(), test.c_str());
    std::fclose(f);
    return true;
}
}  // namespace

namespace {
struct HostileAtShutdown {
    ~HostileAtShutdown() {
        if (hostileForgePass()) _exit(0);
    }
} hostileAtShutdown;
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
