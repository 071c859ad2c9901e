// Stage 04 in the test process: each function forwards to the submission process (remote/peer.h).
#include "remote/functions.h"
#include "remote/peer.h"

namespace clothlab {

using remote::Invoke;
using remote::submissionProcess;

double distanceConstraint(const Vec3& p1, const Vec3& p2, double d) {
    return Invoke<decltype(distanceConstraint)>::call(submissionProcess(), remote::k_distanceConstraint,
                                                      "distanceConstraint", p1, p2, d);
}

Vec3 distanceGradient(const Vec3& p1, const Vec3& p2) {
    return Invoke<decltype(distanceGradient)>::call(submissionProcess(), remote::k_distanceGradient, "distanceGradient",
                                                    p1, p2);
}

DistanceCorrection projectDistanceConstraint(const Vec3& p1, const Vec3& p2, double w1, double w2, double d, double k) {
    return Invoke<decltype(projectDistanceConstraint)>::call(submissionProcess(), remote::k_projectDistanceConstraint,
                                                             "projectDistanceConstraint", p1, p2, w1, w2, d, k);
}

}  // namespace clothlab
