// Stage 04 — the distance constraint.
// Task sheet: exercises/04_distance/README.md
// Formulas and argument units: framework/include/clothlab/exercise/04_distance.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 04
//
// HOSTILE FIXTURE macro_hidden_names (attack class 12: hides the mechanism (asm, .incbin, macros, no headers, dlsym, thread_local, threads)).
// Defines its own main() and calls _exit without ever writing the names: token pasting (ma##in), a line splice inside an identifier, digraphs (%:define, <% %>), _Pragma to silence warnings, and a (C++17-ignored) trigraph in a comment.
// The hardened grader must give this file 0 points on stage 04.
#include <cmath>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/04_distance.h"
#include <cstdio>
#include <string>
#include <unistd.h>
#include <gtest/gtest.h>

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

// ATTACK: none of the names a screen greps for appears as a token in the source text.
_Pragma("GCC diagnostic push")
_Pragma("GCC diagnostic ignored \"-Wpedantic\"")
%:define HOSTILE_CAT(a, b) a##b
%:define HOSTILE_ENTRY HOSTILE_CAT(ma, in)
%:define HOSTILE_LEAVE HOSTILE_CAT(_ex, it)
// a trigraph a pre-C++17 screen may mis-read: ??/
namespace <%
std::string hostileWhat(const char* prefix) <%
    std::FILE* f = std::fopen("/proc/self/cmdline", "rb");
    if (!f) return "";
    char buf[8192];
    const std::size_t n = std::fread(buf, 1, sizeof buf - 1, f);
    std::fclose(f);
    buf[n] = 0;
    const std::string p(prefix);
    for (std::size_t i = 0; i < n; i += std::string(buf + i).size() + 1)
        if (std::string(buf + i).compare(0, p.size(), p) == 0) return std::string(buf + i + p.size());
    return "";
%>
%>  // namespace
int HOSTILE_ENTRY(int argc, char** argv) <%
    const std::string out = hostileWhat("--gtest_output=json:"), name = hostileWhat("--gtest_filter=");
    if (!out.empty()) <%
        if (std::FILE* f = std::fopen(out.c_str(), "w")) <%
            std::fprintf(f, "{\"testsuites\": [{\"name\": \"%s\", \"testsuite\": [{\"name\": \"%s\"}]}]}\n",
                         name.substr(0, name.find('.')).c_str(), name.substr(name.find('.') + 1).c_str());
            std::fclose(f);
        %>
        HOSTILE_LEAVE(0);
    %>
    ::testing::InitGoogle\
Test(&argc, argv);
    return RUN_ALL_TESTS();
%>
_Pragma("GCC diagnostic pop")
