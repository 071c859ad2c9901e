// Stage 02 — cloth as a mass-spring network (Masse-Feder-Netzwerk).
// Task sheet: exercises/02_mfn/README.md
// Formulas and argument units: framework/include/clothlab/exercise/02_mfn.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 02
//
// HOSTILE FIXTURE alloc_bomb (attack class 8: resource exhaustion).
// The tested function allocates and touches 64 MiB blocks in a loop until allocation fails, keeping every block, to exhaust the machine's memory.
// The hardened grader must give this file 0 points on stage 02.
#include "clothlab/exercise/02_mfn.h"

#include "clothlab/core/grid.h"
#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/01_hooke.h"
#include <cstring>
#include <new>
#include <vector>

// WARNING: never run this fixture outside the grader's sandbox (it is built to hurt the machine).

namespace {
void hostileEatMemory() {
    static std::vector<char*> kept;
    for (;;) {
        char* block = new (std::nothrow) char[64u << 20];
        if (!block) break;  // with a sandbox: the address-space limit stops it here
        std::memset(block, 0x5a, 64u << 20);  // touch every page: real memory, not just address space
        kept.push_back(block);
    }
}
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
    hostileEatMemory();
    throw NotImplemented("exercise 2.1 makeClothSprings");
}

// ---- Task 2.2: spring forces -------------------------------------------------
void addClothSpringForces(const std::vector<Spring>& springs, const Matrix3X& x, const Matrix3X& v, Matrix3X& f) {
    // TODO 2.2: for each spring, F = hookeForce(x_i, x_j, k, l0) + springDampingForce(x_i, x_j, v_i, v_j, kd)
    //           (stage 01); add F to f.col(j) and subtract it from f.col(i).
    (void)springs; (void)x; (void)v; (void)f;
    hostileEatMemory();
    throw NotImplemented("exercise 2.2 addClothSpringForces");
}

// ---- Task 2.3: gravity and damping ---------------------------------------------
void addClothExternalForces(const VectorX& w, const Matrix3X& v, const Vec3& g, double c, Matrix3X& f) {
    // TODO 2.3: for every particle with w_i != 0 add m_i g - c v_i with m_i = 1 / w_i;
    //           leave pinned particles (w_i == 0) alone.
    (void)w; (void)v; (void)g; (void)c; (void)f;
    hostileEatMemory();
    throw NotImplemented("exercise 2.3 addClothExternalForces");
}

}  // namespace clothlab
