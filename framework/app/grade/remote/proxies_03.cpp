// Stage 03 in the test process: each function forwards to the submission process (remote/peer.h).
#include "remote/functions.h"
#include "remote/peer.h"

namespace clothlab {

using remote::Invoke;
using remote::submissionProcess;

void dampVelocities(const Matrix3X& x, Matrix3X& v, const VectorX& w, double kDamping) {
    Invoke<decltype(dampVelocities)>::call(submissionProcess(), remote::k_dampVelocities, "dampVelocities", x, v, w,
                                           kDamping);
}

double iterationStiffness(double k, int iterations) {
    return Invoke<decltype(iterationStiffness)>::call(submissionProcess(), remote::k_iterationStiffness,
                                                      "iterationStiffness", k, iterations);
}

void pbdStep(PbdParticles& P, const PbdCallbacks& callbacks, double kDamping, int iterations, double dt) {
    Invoke<decltype(pbdStep)>::call(submissionProcess(), remote::k_pbdStep, "pbdStep", P, callbacks, kDamping, iterations,
                                    dt);
}

}  // namespace clothlab
