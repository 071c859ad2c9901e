// Stage 01 in the test process: each function forwards to the submission process (remote/peer.h).
#include "remote/functions.h"
#include "remote/peer.h"

namespace clothlab {

using remote::Invoke;
using remote::submissionProcess;

Vec3 hookeForce(const Vec3& p0, const Vec3& p1, double k, double l0) {
    return Invoke<decltype(hookeForce)>::call(submissionProcess(), remote::k_hookeForce, "hookeForce", p0, p1, k, l0);
}

Vec3 springDampingForce(const Vec3& p0, const Vec3& p1, const Vec3& v0, const Vec3& v1, double kd) {
    return Invoke<decltype(springDampingForce)>::call(submissionProcess(), remote::k_springDampingForce,
                                                      "springDampingForce", p0, p1, v0, v1, kd);
}

void explicitEulerStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    Invoke<decltype(explicitEulerStep)>::call(submissionProcess(), remote::k_explicitEulerStep, "explicitEulerStep", x, v,
                                              w, force, dt);
}

void symplecticEulerStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    Invoke<decltype(symplecticEulerStep)>::call(submissionProcess(), remote::k_symplecticEulerStep, "symplecticEulerStep",
                                                x, v, w, force, dt);
}

void velocityVerletStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    Invoke<decltype(velocityVerletStep)>::call(submissionProcess(), remote::k_velocityVerletStep, "velocityVerletStep", x,
                                               v, w, force, dt);
}

}  // namespace clothlab
