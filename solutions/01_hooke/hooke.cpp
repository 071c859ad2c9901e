// Stage 01 — Hooke spring and time integration (reference solution).
// Task sheet: exercises/01_hooke/README.md
#include "clothlab/exercise/01_hooke.h"

namespace clothlab {

// ---- Task 1.1: Hooke's law --------------------------------------------------
Vec3 hookeForce(const Vec3& p0, const Vec3& p1, double k, double l0) {
    const Vec3 d = p1 - p0;
    const double length = d.norm();
    if (length < 1e-12) return Vec3::Zero();  // direction undefined
    return -k * (length - l0) * (d / length);
}

// ---- Task 1.2: damping along the spring -------------------------------------
Vec3 springDampingForce(const Vec3& p0, const Vec3& p1, const Vec3& v0, const Vec3& v1, double kd) {
    const Vec3 d = p1 - p0;
    const double length = d.norm();
    if (length < 1e-12) return Vec3::Zero();
    const Vec3 dir = d / length;
    return -kd * (v1 - v0).dot(dir) * dir;
}

// ---- Task 1.3: explicit Euler -----------------------------------------------
void explicitEulerStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    Matrix3X f(3, x.cols());
    force(x, v, f);
    x += dt * v;                                // old velocity
    v += dt * (f * w.asDiagonal());             // a_i = w_i F_i
}

// ---- Task 1.4: symplectic Euler ---------------------------------------------
void symplecticEulerStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    Matrix3X f(3, x.cols());
    force(x, v, f);
    v += dt * (f * w.asDiagonal());
    x += dt * v;                                // new velocity
}

// ---- Task 1.5: velocity Verlet ----------------------------------------------
void velocityVerletStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    Matrix3X f(3, x.cols());
    force(x, v, f);
    v += 0.5 * dt * (f * w.asDiagonal());       // half kick
    x += dt * v;                                // drift
    force(x, v, f);
    v += 0.5 * dt * (f * w.asDiagonal());       // half kick
}

}  // namespace clothlab
