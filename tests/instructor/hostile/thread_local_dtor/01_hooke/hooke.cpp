// Stage 01 — Hooke spring and time integration.
// Task sheet: exercises/01_hooke/README.md
// Formulas and argument units: framework/include/clothlab/exercise/01_hooke.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 01
//
// HOSTILE FIXTURE thread_local_dtor (attack class 12: hides the mechanism (asm, .incbin, macros, no headers, dlsym, thread_local, threads)).
// A thread_local object first touched inside the tested function has a destructor that runs at exit (after GoogleTest wrote its result) and overwrites the JSON with a pass, exiting 0.
// The hardened grader must give this file 0 points on stage 01.
#include "clothlab/exercise/01_hooke.h"
#include "clothlab/core/not_implemented.h"
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
struct HostileTls {
    bool armed = false;
    ~HostileTls() {
        if (armed && hostileForgePass()) _exit(0);  // main thread's thread_local dtors run inside exit()
    }
};
thread_local HostileTls hostileTls;
}  // namespace

namespace clothlab {

// ---- Task 1.1: Hooke's law --------------------------------------------------
Vec3 hookeForce(const Vec3& p0, const Vec3& p1, double k, double l0) {
    // TODO 1.1: F = -k (|p1 - p0| - l0) (p1 - p0) / |p1 - p0|, the force on p1.
    //           Return Vec3::Zero() when p0 and p1 coincide.
    (void)p0; (void)p1; (void)k; (void)l0;
    hostileTls.armed = true;
    throw NotImplemented("exercise 1.1 hookeForce");
}

// ---- Task 1.2: damping along the spring -------------------------------------
Vec3 springDampingForce(const Vec3& p0, const Vec3& p1, const Vec3& v0, const Vec3& v1, double kd) {
    // TODO 1.2: F = -kd ((v1 - v0) . d) d with d the unit vector from p0 to p1.
    (void)p0; (void)p1; (void)v0; (void)v1; (void)kd;
    hostileTls.armed = true;
    throw NotImplemented("exercise 1.2 springDampingForce");
}

// ---- Task 1.3: explicit Euler -----------------------------------------------
void explicitEulerStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    // TODO 1.3: evaluate the forces with force(x, v, f) (f is 3 x N),
    //           then x += dt * v_old and v += dt * w_i * f_i.
    (void)x; (void)v; (void)w; (void)force; (void)dt;
    hostileTls.armed = true;
    throw NotImplemented("exercise 1.3 explicitEulerStep");
}

// ---- Task 1.4: symplectic Euler ---------------------------------------------
void symplecticEulerStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    // TODO 1.4: first the velocity, then the position with the NEW velocity.
    (void)x; (void)v; (void)w; (void)force; (void)dt;
    hostileTls.armed = true;
    throw NotImplemented("exercise 1.4 symplecticEulerStep");
}

// ---- Task 1.5: velocity Verlet ----------------------------------------------
void velocityVerletStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    // TODO 1.5: half kick, drift, forces at the new positions, half kick.
    (void)x; (void)v; (void)w; (void)force; (void)dt;
    hostileTls.armed = true;
    throw NotImplemented("exercise 1.5 velocityVerletStep");
}

}  // namespace clothlab
