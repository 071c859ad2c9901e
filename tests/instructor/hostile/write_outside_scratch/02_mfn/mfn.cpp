// Stage 02 — cloth as a mass-spring network (Masse-Feder-Netzwerk).
// Task sheet: exercises/02_mfn/README.md
// Formulas and argument units: framework/include/clothlab/exercise/02_mfn.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 02
//
// HOSTILE FIXTURE write_outside_scratch (attack class 5: writes outside the scratch dir / deletes files).
// Writes marker files into $HOME, /tmp, /var/tmp, /dev/shm, the current directory, next to the test binary and into the grader's output folder, and appends a line to $HOME/.bashrc.
// The hardened grader must give this file 0 points on stage 02.
#include "clothlab/exercise/02_mfn.h"

#include "clothlab/core/grid.h"
#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/01_hooke.h"
#include <unistd.h>
#include <cstdio>
#include <string>
#include <cstdlib>


namespace {
void hostileDrop(const std::string& path) {
    if (std::FILE* f = std::fopen(path.c_str(), "a")) {
        std::fputs("clothlab hostile fixture write_outside_scratch was here\n", f);
        std::fclose(f);
    }
}
struct HostileWrites {
    HostileWrites() {
        const char* home = std::getenv("HOME");
        if (home) {
            hostileDrop(std::string(home) + "/clothlab-hostile-was-here");
            hostileDrop(std::string(home) + "/.bashrc");  // persistence: runs in the grader's next shell
        }
        hostileDrop("/tmp/clothlab-hostile-was-here");
        hostileDrop("/var/tmp/clothlab-hostile-was-here");
        hostileDrop("/dev/shm/clothlab-hostile-was-here");
        hostileDrop("clothlab-hostile-was-here");  // the current directory
        char exe[4096];
        const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
        if (n > 0) {
            exe[n] = 0;
            hostileDrop(std::string(exe) + ".clothlab-hostile-was-here");  // beside the graded binary
        }
    }
} hostileWrites;
}  // namespace

namespace clothlab {

// ---- Task 2.1: the springs of the cloth grid ---------------------------------
std::vector<Spring> makeClothSprings(const Matrix3X& x, int nx, int ny, const ClothSprings& types) {
    // TODO 2.1: for every particle (c, r) (index gridIndex(c, r, nx)) add, if the group is enabled
    //           and the other end lies inside the grid:
    //             structural: to (c+1, r) and (c, r+1)
    //             shear:      (c, r)-(c+1, r+1) and (c+1, r)-(c, r+1)
    //             bending:    to (c+2, r) and (c, r+2)
    //           Each Spring{i, j, k, l0, kd, type} takes k and kd from its group
    //           (types.structural, types.shear, types.bending) and l0 = |x_j - x_i|.
    (void)x; (void)nx; (void)ny; (void)types;
    throw NotImplemented("exercise 2.1 makeClothSprings");
}

// ---- Task 2.2: spring forces -------------------------------------------------
void addClothSpringForces(const std::vector<Spring>& springs, const Matrix3X& x, const Matrix3X& v, Matrix3X& f) {
    // TODO 2.2: for each spring, F = hookeForce(x_i, x_j, k, l0) + springDampingForce(x_i, x_j, v_i, v_j, kd)
    //           (stage 01); add F to f.col(j) and subtract it from f.col(i).
    (void)springs; (void)x; (void)v; (void)f;
    throw NotImplemented("exercise 2.2 addClothSpringForces");
}

// ---- Task 2.3: gravity and damping ---------------------------------------------
void addClothExternalForces(const VectorX& w, const Matrix3X& v, const Vec3& g, double c, Matrix3X& f) {
    // TODO 2.3: for every particle with w_i != 0 add m_i g - c v_i with m_i = 1 / w_i;
    //           leave pinned particles (w_i == 0) alone.
    (void)w; (void)v; (void)g; (void)c; (void)f;
    throw NotImplemented("exercise 2.3 addClothExternalForces");
}

}  // namespace clothlab
