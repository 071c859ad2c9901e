// Stage 02 — cloth as a mass-spring network (Masse-Feder-Netzwerk).
// Task sheet: exercises/02_mfn/README.md
// Formulas and argument units: framework/include/clothlab/exercise/02_mfn.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 02
//
// HOSTILE FIXTURE has_include_probe (attack class 4: #include of the instructor's files).
// Probes with __has_include for the reference (relative through the -I paths and absolute), the test source and the points file, includes the reference when found and records in a string what the compiler could see.
// The hardened grader must give this file 0 points on stage 02.
// ATTACK: a compile-time scan of the instructor's tree. Each probe that succeeds is recorded in
// kHostileSeen (the binary then knows where the tree is); the reference is compiled in if found.
#if __has_include("../../tests/02_mfn.points.json")
#define HOSTILE_SEEN_POINTS "points file visible via -I/../../tests; "
#else
#define HOSTILE_SEEN_POINTS ""
#endif
#if __has_include("../../tests/02_mfn_test.cpp")
#define HOSTILE_SEEN_TEST "test source visible; "
#else
#define HOSTILE_SEEN_TEST ""
#endif
#if __has_include("../../solutions/02_mfn/mfn.cpp")
#include "../../solutions/02_mfn/mfn.cpp"
#define HOSTILE_GOT_REFERENCE "reference via -I/../../solutions"
#elif __has_include("../../../solutions/02_mfn/mfn.cpp")
#include "../../../solutions/02_mfn/mfn.cpp"
#define HOSTILE_GOT_REFERENCE "reference via -I/../../../solutions"
#elif __has_include(</work/main/solutions/02_mfn/mfn.cpp>)
#include </work/main/solutions/02_mfn/mfn.cpp>
#define HOSTILE_GOT_REFERENCE "reference via /work/main"
#endif
extern const char* const kHostileSeen;
#ifdef HOSTILE_GOT_REFERENCE
const char* const kHostileSeen = HOSTILE_SEEN_POINTS HOSTILE_SEEN_TEST HOSTILE_GOT_REFERENCE;
#else
const char* const kHostileSeen = HOSTILE_SEEN_POINTS HOSTILE_SEEN_TEST "no reference";
#include "clothlab/exercise/02_mfn.h"

#include "clothlab/core/grid.h"
#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/01_hooke.h"

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
#endif  // HOSTILE_GOT_REFERENCE
