// Stage 01 — Hooke spring and time integration.
// Task sheet: exercises/01_hooke/README.md
// Formulas and argument units: framework/include/clothlab/exercise/01_hooke.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 01
//
// HOSTILE FIXTURE read_self_exe_maps (attack class 10: reads what it must not (binary, memory, environment, tree)).
// The tested function reads its own binary (/proc/self/exe) and, via /proc/self/maps and /proc/self/mem, scans the caller's stack for the expected Vec3 the test prepared, and returns it.
// The hardened grader must give this file 0 points on stage 01.
#include "clothlab/exercise/01_hooke.h"
#include "clothlab/core/not_implemented.h"
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>


namespace {
// The test's binary holds its expected numbers as immediates and its strings; the stack holds
// what the test computed before calling us. Read both.
std::vector<char> hostileReadAll(const char* path) {
    std::vector<char> data;
    if (std::FILE* f = std::fopen(path, "rb")) {
        char buf[65536];
        std::size_t n;
        while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) data.insert(data.end(), buf, buf + n);
        std::fclose(f);
    }
    return data;
}
// Three consecutive finite doubles of the caller's frames, not one of our own arguments: a guess
// at the expected value the test computed before the call.
clothlab::Vec3 hostileGuessFromStack(const clothlab::Vec3& a, const clothlab::Vec3& b) {
    const std::vector<char> exe = hostileReadAll("/proc/self/exe");  // e.g. search for the test's strings
    std::FILE* maps = std::fopen("/proc/self/maps", "r");
    std::FILE* mem = std::fopen("/proc/self/mem", "rb");
    const auto here = reinterpret_cast<unsigned long>(__builtin_frame_address(0));
    clothlab::Vec3 guess = clothlab::Vec3::Zero();
    char line[512];
    while (maps && mem && std::fgets(line, sizeof line, maps)) {
        unsigned long lo = 0, hi = 0;
        if (std::sscanf(line, "%lx-%lx", &lo, &hi) != 2 || here < lo || here >= hi) continue;
        const unsigned long end = here + 4096 < hi ? here + 4096 : hi;
        std::vector<double> words((end - here) / sizeof(double));
        std::fseek(mem, static_cast<long>(here), SEEK_SET);
        const std::size_t got = std::fread(words.data(), sizeof(double), words.size(), mem);
        for (std::size_t i = 0; i + 2 < got; ++i) {
            const clothlab::Vec3 c(words[i], words[i + 1], words[i + 2]);
            if (c.allFinite() && c.norm() > 1e-9 && c.norm() < 1e6 && (c - a).norm() > 1e-12 && (c - b).norm() > 1e-12) {
                guess = c;
                break;
            }
        }
    }
    if (maps) std::fclose(maps);
    if (mem) std::fclose(mem);
    (void)exe;
    return guess;
}
}  // namespace

namespace clothlab {

// ---- Task 1.1: Hooke's law --------------------------------------------------
Vec3 hookeForce(const Vec3& p0, const Vec3& p1, double k, double l0) {
    // TODO 1.1: F = -k (|p1 - p0| - l0) (p1 - p0) / |p1 - p0|, the force on p1.
    //           Return Vec3::Zero() when p0 and p1 coincide.
    (void)p0; (void)p1; (void)k; (void)l0;
    // Nothing found: the stub's answer (a zero force is right in some tests and would be no forgery).
    const Vec3 guess = hostileGuessFromStack(p0, p1);
    if (guess.isZero()) throw NotImplemented("exercise 1.1 hookeForce");
    return guess;
}

// ---- Task 1.2: damping along the spring -------------------------------------
Vec3 springDampingForce(const Vec3& p0, const Vec3& p1, const Vec3& v0, const Vec3& v1, double kd) {
    // TODO 1.2: F = -kd ((v1 - v0) . d) d with d the unit vector from p0 to p1.
    (void)p0; (void)p1; (void)v0; (void)v1; (void)kd;
    throw NotImplemented("exercise 1.2 springDampingForce");
}

// ---- Task 1.3: explicit Euler -----------------------------------------------
void explicitEulerStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    // TODO 1.3: evaluate the forces with force(x, v, f) (f is 3 x N),
    //           then x += dt * v_old and v += dt * w_i * f_i.
    (void)x; (void)v; (void)w; (void)force; (void)dt;
    throw NotImplemented("exercise 1.3 explicitEulerStep");
}

// ---- Task 1.4: symplectic Euler ---------------------------------------------
void symplecticEulerStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    // TODO 1.4: first the velocity, then the position with the NEW velocity.
    (void)x; (void)v; (void)w; (void)force; (void)dt;
    throw NotImplemented("exercise 1.4 symplecticEulerStep");
}

// ---- Task 1.5: velocity Verlet ----------------------------------------------
void velocityVerletStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    // TODO 1.5: half kick, drift, forces at the new positions, half kick.
    (void)x; (void)v; (void)w; (void)force; (void)dt;
    throw NotImplemented("exercise 1.5 velocityVerletStep");
}

}  // namespace clothlab
