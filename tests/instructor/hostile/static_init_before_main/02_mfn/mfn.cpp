// Stage 02 stub + a namespace-scope static whose initialiser dereferences a null pointer.
// The initialiser has no outside call and no relocation (at most `.bss`, its own variable), so the
// object screen's .init_array check (calls in .text.startup limited to ios_base::Init,
// __cxa_atexit, .bss) accepts it: code DOES run before main(). Here it only crashes every test
// (status 139 before `start`, 0 points); a relocation-free initialiser could equally find libc
// through the return addresses on its stack (see channel_forge_libc_walk) and read the channel
// secret from fd 3 before the graded main() does. If the grader ever lists tests of a submission's
// binary (gradeBinary's --gtest_list_tests + die()), this same file stops the whole run.
// Stage 02 — cloth as a mass-spring network (Masse-Feder-Netzwerk).
// Task sheet: exercises/02_mfn/README.md
// Formulas and argument units: framework/include/clothlab/exercise/02_mfn.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 02
#include "clothlab/exercise/02_mfn.h"

#include "clothlab/core/grid.h"
#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/01_hooke.h"


namespace {
int crashOnLoad() {
    volatile int* volatile nowhere = nullptr;
    *nowhere = 1;  // SIGSEGV before main()
    return 0;
}
int loaded = crashOnLoad();
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
