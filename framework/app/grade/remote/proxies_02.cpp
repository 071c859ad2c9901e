// Stage 02 in the test process: each function forwards to the submission process (remote/peer.h).
#include "remote/functions.h"
#include "remote/peer.h"

namespace clothlab {

using remote::Invoke;
using remote::submissionProcess;

std::vector<Spring> makeClothSprings(const Matrix3X& x, int nx, int ny, const ClothSprings& types) {
    std::vector<Spring> springs = Invoke<decltype(makeClothSprings)>::call(
        submissionProcess(), remote::k_makeClothSprings, "makeClothSprings", x, nx, ny, types);
    // The framework indexes particles with these: an index outside 0..N-1 is refused here.
    for (const Spring& s : springs)
        if (s.i < 0 || s.j < 0 || s.i >= x.cols() || s.j >= x.cols())
            throw std::out_of_range("makeClothSprings returned a spring between particles " + std::to_string(s.i) + " and " +
                                    std::to_string(s.j) + ", but there are " + std::to_string(x.cols()) + " (0.." +
                                    std::to_string(x.cols() - 1) + ")");
    return springs;
}

void addClothSpringForces(const std::vector<Spring>& springs, const Matrix3X& x, const Matrix3X& v, Matrix3X& f) {
    Invoke<decltype(addClothSpringForces)>::call(submissionProcess(), remote::k_addClothSpringForces,
                                                 "addClothSpringForces", springs, x, v, f);
}

void addClothExternalForces(const VectorX& w, const Matrix3X& v, const Vec3& g, double c, Matrix3X& f) {
    Invoke<decltype(addClothExternalForces)>::call(submissionProcess(), remote::k_addClothExternalForces,
                                                   "addClothExternalForces", w, v, g, c, f);
}

}  // namespace clothlab
