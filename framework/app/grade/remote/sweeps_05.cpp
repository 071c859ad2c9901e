// Stage 05's framework sweeps in the test process: when the stage's code is the submission's, the
// grader links these in place of the framework's own (sim/sweeps.cpp defines those weak), and a
// sweep crosses to the submission process whole, once per solver iteration (remote/functions.h).
#include "remote/functions.h"
#include "remote/peer.h"

namespace clothlab {

using remote::Invoke;
using remote::submissionProcess;

void projectBendingSweep(const std::vector<BendingStencil>& stencils, const VectorX& w, double k, Matrix3X& p, const SweepPlan& plan) {
    Invoke<decltype(projectBendingSweep)>::call(submissionProcess(), remote::k_projectBendingSweep, "projectBendingSweep", stencils, w, k, p, serialPlan(plan));
}

void projectBendingSweepXpbd(const std::vector<BendingStencil>& stencils, const VectorX& w, double alphaTilde,
                             std::vector<double>& lambda, Matrix3X& p, const SweepPlan& plan) {
    Invoke<decltype(projectBendingSweepXpbd)>::call(submissionProcess(), remote::k_projectBendingSweepXpbd, "projectBendingSweepXpbd", stencils, w, alphaTilde, lambda, p, serialPlan(plan));
}

}  // namespace clothlab
