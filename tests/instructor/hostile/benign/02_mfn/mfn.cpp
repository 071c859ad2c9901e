// Stage 02 — cloth as a mass-spring network (Masse-Feder-Netzwerk).
// Task sheet: exercises/02_mfn/README.md
// Formulas and argument units: framework/include/clothlab/exercise/02_mfn.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 02
//
// BENIGN FIXTURE: the stub with harmless student additions. It scores 0 (every task still
// throws NotImplemented) but a careful screen must ACCEPT it: nothing here is an attack.
#include "clothlab/exercise/02_mfn.h"

#include "clothlab/core/grid.h"
#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/01_hooke.h"
#include <algorithm>
#include <cstdio>
#include <vector>


// Harmless student additions: a global-namespace helper, a constexpr table, a lambda, printf.
int clampIndex(int i, int n) { return std::max(0, std::min(i, n - 1)); }

namespace {
constexpr int kNeighbours[4][2] = {{1, 0}, {0, 1}, {1, 1}, {2, 0}};
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
    const auto count = [](const std::vector<int>& v) { return static_cast<int>(v.size()); };
    std::printf("debug: %d neighbour offsets, clamp %d, %d\n", 4, clampIndex(kNeighbours[3][0], 2), count({1, 2}));
    throw NotImplemented("exercise 2.1 makeClothSprings");
}

// ---- Task 2.2: spring forces -------------------------------------------------
void addClothSpringForces(const std::vector<Spring>& springs, const Matrix3X& x, const Matrix3X& v, Matrix3X& f) {
    // TODO 2.2: for each spring, F = hookeForce(x_i, x_j, k, l0) + springDampingForce(x_i, x_j, v_i, v_j, kd)
    //           (stage 01); add F to f.col(j) and subtract it from f.col(i).
    (void)springs; (void)x; (void)v; (void)f;
    const auto count = [](const std::vector<int>& v) { return static_cast<int>(v.size()); };
    std::printf("debug: %d neighbour offsets, clamp %d, %d\n", 4, clampIndex(kNeighbours[3][0], 2), count({1, 2}));
    throw NotImplemented("exercise 2.2 addClothSpringForces");
}

// ---- Task 2.3: gravity and damping ---------------------------------------------
void addClothExternalForces(const VectorX& w, const Matrix3X& v, const Vec3& g, double c, Matrix3X& f) {
    // TODO 2.3: for every particle with w_i != 0 add m_i g - c v_i with m_i = 1 / w_i;
    //           leave pinned particles (w_i == 0) alone.
    (void)w; (void)v; (void)g; (void)c; (void)f;
    const auto count = [](const std::vector<int>& v) { return static_cast<int>(v.size()); };
    std::printf("debug: %d neighbour offsets, clamp %d, %d\n", 4, clampIndex(kNeighbours[3][0], 2), count({1, 2}));
    throw NotImplemented("exercise 2.3 addClothExternalForces");
}

}  // namespace clothlab
