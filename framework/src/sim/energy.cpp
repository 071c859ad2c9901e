#include "clothlab/sim/energy.h"

namespace clothlab {

double kineticEnergy(const VectorX& w, const Matrix3X& v) {
    double e = 0.0;
    for (int i = 0; i < w.size(); ++i)
        if (w[i] > 0.0) e += 0.5 * v.col(i).squaredNorm() / w[i];
    return e;
}

double gravityEnergy(const VectorX& w, const Matrix3X& x, const Vec3& g) {
    double e = 0.0;
    for (int i = 0; i < w.size(); ++i)
        if (w[i] > 0.0) e -= g.dot(x.col(i)) / w[i];
    return e;
}

double springEnergy(const std::vector<Spring>& springs, const Matrix3X& x) {
    double e = 0.0;
    for (const Spring& s : springs) {
        const double stretch = (x.col(s.j) - x.col(s.i)).norm() - s.l0;
        e += 0.5 * s.k * stretch * stretch;
    }
    return e;
}

}  // namespace clothlab
