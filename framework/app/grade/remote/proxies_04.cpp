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

// The framework's sweeps over this stage's constraints, sent whole (remote/functions.h: 901–905).

void wrappedDistanceSweep(const std::vector<DistanceLink>& links, const VectorX& w, double k, Matrix3X& p, const SweepPlan& plan) __asm__("__wrap__ZN8clothlab20projectDistanceSweepERKSt6vectorINS_12DistanceLinkESaIS1_EERKN5Eigen6MatrixIdLin1ELi1ELi0ELin1ELi1EEEdRNS7_IdLi3ELin1ELi0ELi3ELin1EEERKNS_9SweepPlanE");
void wrappedDistanceSweep(const std::vector<DistanceLink>& links, const VectorX& w, double k, Matrix3X& p, const SweepPlan& plan) {
    Invoke<decltype(projectDistanceSweep)>::call(submissionProcess(), remote::k_projectDistanceSweep, "projectDistanceSweep", links, w, k, p, serialPlan(plan));
}

void wrappedDistanceSweepXpbd(const std::vector<DistanceLink>& links, const VectorX& w, double alphaTilde,
                               std::vector<double>& lambda, Matrix3X& p, const SweepPlan& plan) __asm__("__wrap__ZN8clothlab24projectDistanceSweepXpbdERKSt6vectorINS_12DistanceLinkESaIS1_EERKN5Eigen6MatrixIdLin1ELi1ELi0ELin1ELi1EEEdRS0_IdSaIdEERNS7_IdLi3ELin1ELi0ELi3ELin1EEERKNS_9SweepPlanE");
void wrappedDistanceSweepXpbd(const std::vector<DistanceLink>& links, const VectorX& w, double alphaTilde,
                               std::vector<double>& lambda, Matrix3X& p, const SweepPlan& plan) {
    Invoke<decltype(projectDistanceSweepXpbd)>::call(submissionProcess(), remote::k_projectDistanceSweepXpbd, "projectDistanceSweepXpbd", links, w, alphaTilde, lambda, p, serialPlan(plan));
}

}  // namespace clothlab
