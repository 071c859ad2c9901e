// Stage 05's framework sweeps in the test process: sent whole to the submission process when the
// stage's code is the submission's (remote/functions.h: 901–906; the grader links with --wrap).
#include "remote/functions.h"
#include "remote/peer.h"

namespace clothlab {

using remote::Invoke;
using remote::submissionProcess;

void wrappedBendingSweep(const std::vector<BendingStencil>& stencils, const VectorX& w, double k, Matrix3X& p, const SweepPlan& plan) __asm__("__wrap__ZN8clothlab19projectBendingSweepERKSt6vectorINS_14BendingStencilESaIS1_EERKN5Eigen6MatrixIdLin1ELi1ELi0ELin1ELi1EEEdRNS7_IdLi3ELin1ELi0ELi3ELin1EEERKNS_9SweepPlanE");
void wrappedBendingSweep(const std::vector<BendingStencil>& stencils, const VectorX& w, double k, Matrix3X& p, const SweepPlan& plan) {
    Invoke<decltype(projectBendingSweep)>::call(submissionProcess(), remote::k_projectBendingSweep, "projectBendingSweep", stencils, w, k, p, serialPlan(plan));
}

void wrappedBendingSweepXpbd(const std::vector<BendingStencil>& stencils, const VectorX& w, double alphaTilde,
                              std::vector<double>& lambda, Matrix3X& p, const SweepPlan& plan) __asm__("__wrap__ZN8clothlab23projectBendingSweepXpbdERKSt6vectorINS_14BendingStencilESaIS1_EERKN5Eigen6MatrixIdLin1ELi1ELi0ELin1ELi1EEEdRS0_IdSaIdEERNS7_IdLi3ELin1ELi0ELi3ELin1EEERKNS_9SweepPlanE");
void wrappedBendingSweepXpbd(const std::vector<BendingStencil>& stencils, const VectorX& w, double alphaTilde,
                              std::vector<double>& lambda, Matrix3X& p, const SweepPlan& plan) {
    Invoke<decltype(projectBendingSweepXpbd)>::call(submissionProcess(), remote::k_projectBendingSweepXpbd, "projectBendingSweepXpbd", stencils, w, alphaTilde, lambda, p, serialPlan(plan));
}

}  // namespace clothlab
