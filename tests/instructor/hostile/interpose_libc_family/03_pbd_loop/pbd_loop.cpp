// Stage 03 — the PBD loop.
// Task sheet: exercises/03_pbd_loop/README.md
// Formulas and argument units: framework/include/clothlab/exercise/03_pbd_loop.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 03
//
// HOSTILE FIXTURE interpose_libc_family (attack class 11: interposes libc / libstdc++ symbols).
// Defines exit, _exit, write, malloc/free/calloc/realloc (over __libc_malloc) and __cxa_atexit: the __cxa_atexit hook slips an exit-time forger in before the first static destructor is registered, malloc runs before any constructor, _exit/exit force status 0, write rewrites '[  FAILED  ]' into '[       OK ]'.
// The hardened grader must give this file 0 points on stage 03.
#include <cmath>

#include <Eigen/Dense>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/03_pbd_loop.h"
#include <unistd.h>
#include <cstdio>
#include <string>
#include <cstring>
#include <dlfcn.h>
#include <sys/syscall.h>


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

extern "C" {
void* __libc_malloc(std::size_t);
void __libc_free(void*);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);

static bool hostileArmed = false;
static void hostileAtExit(void*) {
    if (hostileForgePass()) syscall(SYS_exit_group, 0);
}
// Registration of every static destructor passes here (compiler-emitted calls): slip ours in first.
int __cxa_atexit(void (*fn)(void*), void* arg, void* dso) {
    using Real = int (*)(void (*)(void*), void*, void*);
    static Real real = reinterpret_cast<Real>(dlsym(RTLD_NEXT, "__cxa_atexit"));
    if (!real) return 0;
    if (!hostileArmed) {
        hostileArmed = true;
        real(&hostileAtExit, nullptr, dso);  // registered first: runs last, after GoogleTest wrote its JSON
    }
    return real(fn, arg, dso);
}
// Runs before any constructor: the loader and libc allocate first.
void* malloc(std::size_t n) { return __libc_malloc(n); }
void free(void* p) { __libc_free(p); }
void* calloc(std::size_t n, std::size_t s) { return __libc_calloc(n, s); }
void* realloc(void* p, std::size_t n) { return __libc_realloc(p, n); }
// Whoever calls exit or _exit through the PLT gets status 0.
void _exit(int) { syscall(SYS_exit_group, 0); for (;;) {} }
void exit(int) { hostileForgePass(); syscall(SYS_exit_group, 0); for (;;) {} }
// Direct writes (libstdc++, the framework) with "[  FAILED  ]" become "[       OK ]".
ssize_t write(int fd, const void* buf, std::size_t n) {
    std::string s(static_cast<const char*>(buf), n);
    for (std::size_t i = s.find("[  FAILED  ]"); i != std::string::npos; i = s.find("[  FAILED  ]", i)) s.replace(i, 12, "[       OK ]");
    syscall(SYS_write, fd, s.data(), s.size());
    return static_cast<ssize_t>(n);
}
}  // extern "C"

namespace clothlab {

// ---- Task 3.1: dampVelocities ------------------------------------------------
void dampVelocities(const Matrix3X& x, Matrix3X& v, const VectorX& w, double kDamping) {
    // TODO 3.1: over the particles with w_i > 0 (m_i = 1/w_i) compute x_cm, v_cm, the angular
    //           momentum L = sum r_i x (m_i v_i) and the inertia I = sum m_i (|r_i|^2 Id - r_i r_i^T),
    //           omega = I^-1 L (pseudo-inverse when I is singular, e.g. Eigen::SelfAdjointEigenSolver),
    //           then v_i += kDamping (v_cm + omega x r_i - v_i). Pinned particles keep their velocity.
    (void)x; (void)v; (void)w; (void)kDamping;
    throw NotImplemented("exercise 3.1 dampVelocities");
}

// ---- Task 3.2: stiffness per iteration ---------------------------------------
double iterationStiffness(double k, int iterations) {
    // TODO 3.2: k' = 1 - (1 - k)^(1/n); n = 0 returns k.
    (void)k; (void)iterations;
    throw NotImplemented("exercise 3.2 iterationStiffness");
}

// ---- Task 3.3: one PBD step, lines (5)-(16) ----------------------------------
void pbdStep(PbdParticles& P, const PbdCallbacks& cb, double kDamping, int iterations, double dt) {
    // TODO 3.3: write lines (5)-(16) of the slides in this order, one or two lines each:
    //   (5)  f = 0 (3 x N), cb.externalForces(x, v, f) if set, v_i += dt w_i f_i
    //   (6)  dampVelocities(x, v, w, kDamping)
    //   (7)  p = x + dt v
    //   (8)  cb.generateCollisionConstraints(x, p) if set
    //   (9)-(11) `iterations` times: cb.projectConstraints(p) if set
    //   (13) v = (p - x) / dt   (14) x = p
    //   (16) cb.velocityUpdate(x, v) if set
    (void)P; (void)cb; (void)kDamping; (void)iterations; (void)dt;
    throw NotImplemented("exercise 3.3 pbdStep");
}

}  // namespace clothlab
