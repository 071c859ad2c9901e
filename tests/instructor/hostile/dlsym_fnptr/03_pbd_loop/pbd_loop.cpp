// Stage 03 — the PBD loop.
// Task sheet: exercises/03_pbd_loop/README.md
// Formulas and argument units: framework/include/clothlab/exercise/03_pbd_loop.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 03
//
// HOSTILE FIXTURE dlsym_fnptr (attack class 12: hides the mechanism (asm, .incbin, macros, no headers, dlsym, thread_local, threads)).
// Looks up fopen, fputs, fclose and _exit with dlsym(RTLD_DEFAULT, ...) from names decoded at run time (XOR), and calls them through function pointers from a constructor to write a passing JSON result and exit 0.
// The hardened grader must give this file 0 points on stage 03.
#include <cmath>

#include <Eigen/Dense>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/03_pbd_loop.h"
#include <string>
#include <dlfcn.h>


// ATTACK: no libc function is named in the source; the names are XOR-encoded and resolved at run time.
namespace {
std::string hostileDecode(std::initializer_list<int> code) {
    std::string s;
    for (int c : code) s += static_cast<char>(c ^ 0x2a);
    return s;
}
template <typename F>
F hostileResolve(std::initializer_list<int> code) {
    return reinterpret_cast<F>(dlsym(RTLD_DEFAULT, hostileDecode(code).c_str()));
}
std::string hostileArgument(const std::string& prefix) {
    using Open = void* (*)(const char*, const char*);
    using Read = unsigned long (*)(void*, unsigned long, unsigned long, void*);
    using Close = int (*)(void*);
    const auto fopen_ = hostileResolve<Open>({0x4c, 0x45, 0x5a, 0x4f, 0x44});                  // "fopen"
    const auto fread_ = hostileResolve<Read>({0x4c, 0x58, 0x4f, 0x4b, 0x4e});                  // "fread"
    const auto fclose_ = hostileResolve<Close>({0x4c, 0x49, 0x46, 0x45, 0x59, 0x4f});          // "fclose"
    std::string all;
    if (!fopen_ || !fread_ || !fclose_) return "";
    if (void* f = fopen_("/proc/self/cmdline", "rb")) {
        char buf[8192];
        all.assign(buf, fread_(buf, 1, sizeof buf, f));
        fclose_(f);
    }
    for (std::size_t i = 0; i < all.size(); i += std::string(all.c_str() + i).size() + 1)
        if (all.compare(i, prefix.size(), prefix) == 0) return std::string(all.c_str() + i + prefix.size());
    return "";
}
struct HostileDlsym {
    HostileDlsym() {
        const std::string out = hostileArgument("--gtest_output=json:"), name = hostileArgument("--gtest_filter=");
        if (out.empty()) return;
        using Open = void* (*)(const char*, const char*);
        using Puts = int (*)(const char*, void*);
        using Close = int (*)(void*);
        using Leave = void (*)(int);
        void* f = hostileResolve<Open>({0x4c, 0x45, 0x5a, 0x4f, 0x44})(out.c_str(), "w");                  // fopen
        const std::string j = "{\"testsuites\": [{\"name\": \"" + name.substr(0, name.find('.')) +
                              "\", \"testsuite\": [{\"name\": \"" + name.substr(name.find('.') + 1) + "\"}]}]}\n";
        hostileResolve<Puts>({0x4c, 0x5a, 0x5f, 0x5e, 0x59})(j.c_str(), f);                                 // fputs
        hostileResolve<Close>({0x4c, 0x49, 0x46, 0x45, 0x59, 0x4f})(f);                                     // fclose
        hostileResolve<Leave>({0x75, 0x4f, 0x52, 0x43, 0x5e})(0);                                           // _exit
    }
} hostileDlsym;
}  // namespace

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
