// Stage 04's framework sweeps in the test process: sent whole to the submission process when the
// stage's code is the submission's (remote/functions.h: 901–906; the grader links with --wrap).
#include "remote/functions.h"
#include "remote/peer.h"

namespace clothlab {

using remote::Invoke;
using remote::submissionProcess;

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
