#include "clothlab/sim/rk4.h"

namespace clothlab {

void rk4Step(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    const Eigen::Index n = x.cols();
    Matrix3X f(3, n);
    auto accel = [&](const Matrix3X& xs, const Matrix3X& vs) {
        force(xs, vs, f);
        return Matrix3X(f * w.asDiagonal());
    };
    const Matrix3X k1x = v, k1v = accel(x, v);
    const Matrix3X k2x = v + 0.5 * dt * k1v, k2v = accel(x + 0.5 * dt * k1x, k2x);
    const Matrix3X k3x = v + 0.5 * dt * k2v, k3v = accel(x + 0.5 * dt * k2x, k3x);
    const Matrix3X k4x = v + dt * k3v, k4v = accel(x + dt * k3x, k4x);
    x += dt / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
    v += dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
}

}  // namespace clothlab
