// Stage 02 — cloth as a mass-spring network (reference solution).
// Task sheet: exercises/02_mfn/README.md
#include "clothlab/exercise/02_mfn.h"

#include "clothlab/core/grid.h"
#include "clothlab/exercise/01_hooke.h"

namespace clothlab {

// ---- Task 2.1: the springs of the cloth grid ---------------------------------
std::vector<Spring> makeClothSprings(const Matrix3X& x, int nx, int ny, const ClothSprings& types) {
    std::vector<Spring> springs;
    // One spring from particle (c0, r0) to (c1, r1), if both lie inside the grid.
    auto connect = [&](int c0, int r0, int c1, int r1, const SpringGroup& group, SpringType type) {
        if (c0 < 0 || c1 < 0 || c0 >= nx || c1 >= nx || r0 >= ny || r1 >= ny) return;
        const int i = gridIndex(c0, r0, nx), j = gridIndex(c1, r1, nx);
        const double l0 = (x.col(j) - x.col(i)).norm();  // rest length from the initial grid
        springs.push_back({i, j, group.k, l0, group.kd, type});
    };
    for (int r = 0; r < ny; ++r)
        for (int c = 0; c < nx; ++c) {
            if (types.structural.enabled) {
                connect(c, r, c + 1, r, types.structural, SpringType::Structural);
                connect(c, r, c, r + 1, types.structural, SpringType::Structural);
            }
            if (types.shear.enabled) {
                connect(c, r, c + 1, r + 1, types.shear, SpringType::Shear);
                connect(c + 1, r, c, r + 1, types.shear, SpringType::Shear);
            }
            if (types.bending.enabled) {
                connect(c, r, c + 2, r, types.bending, SpringType::Bending);
                connect(c, r, c, r + 2, types.bending, SpringType::Bending);
            }
        }
    return springs;
}

// ---- Task 2.2: spring forces -------------------------------------------------
void addClothSpringForces(const std::vector<Spring>& springs, const Matrix3X& x, const Matrix3X& v, Matrix3X& f) {
    for (const Spring& s : springs) {
        const Vec3 force = hookeForce(x.col(s.i), x.col(s.j), s.k, s.l0) +
                           springDampingForce(x.col(s.i), x.col(s.j), v.col(s.i), v.col(s.j), s.kd);
        f.col(s.j) += force;  // force on p1 = x_j
        f.col(s.i) -= force;  // actio = reactio
    }
}

// ---- Task 2.3: gravity and damping ---------------------------------------------
void addClothExternalForces(const VectorX& w, const Matrix3X& v, const Vec3& g, double c, Matrix3X& f) {
    for (Eigen::Index i = 0; i < w.size(); ++i) {
        if (w[i] == 0.0) continue;  // pinned: infinite mass
        f.col(i) += g / w[i] - c * v.col(i);
    }
}

}  // namespace clothlab
