#include "clothlab/sim/forces.h"

#include "clothlab/exercise/01_hooke.h"

namespace clothlab {

void addGravityForces(const VectorX& w, const Vec3& g, Matrix3X& f) {
    for (Eigen::Index i = 0; i < w.size(); ++i)
        if (w[i] > 0.0) f.col(i) += g / w[i];
}

void addVelocityDamping(const Matrix3X& v, double c, Matrix3X& f) { f -= c * v; }

void addSpringForces(const std::vector<Spring>& springs, const Matrix3X& x, const Matrix3X& v, Matrix3X& f) {
    for (const Spring& s : springs) {
        Vec3 force = hookeForce(x.col(s.i), x.col(s.j), s.k, s.l0);
        if (s.kd > 0.0) force += springDampingForce(x.col(s.i), x.col(s.j), v.col(s.i), v.col(s.j), s.kd);
        f.col(s.j) += force;
        f.col(s.i) -= force;
    }
}

double kineticEnergy(const VectorX& w, const Matrix3X& v) {
    double e = 0.0;
    for (Eigen::Index i = 0; i < w.size(); ++i)
        if (w[i] > 0.0) e += 0.5 * v.col(i).squaredNorm() / w[i];
    return e;
}

double gravityEnergy(const VectorX& w, const Matrix3X& x, const Vec3& g) {
    double e = 0.0;
    for (Eigen::Index i = 0; i < w.size(); ++i)
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
