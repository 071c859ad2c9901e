// Stage 01 — Hooke spring and time integration.
// Task sheet: exercises/01_hooke/README.md
// Formulas and argument units: framework/include/clothlab/exercise/01_hooke.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 01
//
// HOSTILE FIXTURE interpose_fopen (attack class 11: interposes libc / libstdc++ symbols).
// Defines libc's fopen: when GoogleTest opens its JSON output file at the end of the run, writes a passing result instead and exits 0; every other fopen goes through open()+fdopen().
// The hardened grader must give this file 0 points on stage 01.
#include "clothlab/exercise/01_hooke.h"
#include "clothlab/core/not_implemented.h"
#include <cstdio>
#include <cstring>
#include <string>
#include <fcntl.h>
#include <unistd.h>


// ATTACK: the executable's fopen preempts libc's for GoogleTest (linked statically) and, as the
// executable exports it, for libstdc++ too.
namespace {
std::string hostileFilter() {
    std::string all, p = "--gtest_filter=";
    const int fd = open("/proc/self/cmdline", O_RDONLY);
    char buf[4096];
    ssize_t n;
    while (fd >= 0 && (n = read(fd, buf, sizeof buf)) > 0) all.append(buf, static_cast<std::size_t>(n));
    if (fd >= 0) close(fd);
    for (std::size_t i = 0; i < all.size(); i = all.find('\0', i) == std::string::npos ? all.size() : all.find('\0', i) + 1)
        if (all.compare(i, p.size(), p) == 0) return std::string(all.c_str() + i + p.size());
    return "";
}
}  // namespace
extern "C" FILE* fopen(const char* path, const char* mode) {
    int flags = O_RDONLY;
    if (std::strchr(mode, 'w')) flags = O_WRONLY | O_CREAT | O_TRUNC;
    if (std::strchr(mode, 'a')) flags = O_WRONLY | O_CREAT | O_APPEND;
    if (std::strchr(mode, '+')) flags = (flags & ~(O_RDONLY | O_WRONLY)) | O_RDWR;
    const std::size_t len = std::strlen(path);
    if ((flags & O_CREAT) && len > 5 && std::strcmp(path + len - 5, ".json") == 0) {
        const std::string name = hostileFilter(), suite = name.substr(0, name.find('.')), test = name.substr(name.find('.') + 1);
        const std::string j = "{\"testsuites\": [{\"name\": \"" + suite + "\", \"testsuite\": [{\"name\": \"" + test + "\"}]}]}\n";
        const int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0 && write(fd, j.data(), j.size()) > 0) _exit(0);  // the run is over: leave with 0
    }
    const int fd = open(path, flags, 0644);
    return fd < 0 ? nullptr : fdopen(fd, mode);
}

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
