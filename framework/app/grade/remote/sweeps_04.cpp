// Stage 04's framework sweeps in the test process: when the stage's code is the submission's, the
// grader links these in place of the framework's own (sim/sweeps.cpp defines those weak), and a
// sweep crosses to the submission process whole, once per solver iteration (remote/functions.h).
#include "remote/functions.h"
#include "remote/peer.h"

namespace clothlab {

using remote::Invoke;
using remote::submissionProcess;

void projectDistanceSweep(const std::vector<DistanceLink>& links, const VectorX& w, double k, Matrix3X& p, const SweepPlan& plan) {
    Invoke<decltype(projectDistanceSweep)>::call(submissionProcess(), remote::k_projectDistanceSweep, "projectDistanceSweep", links, w, k, p, serialPlan(plan));
}

void projectDistanceSweepXpbd(const std::vector<DistanceLink>& links, const VectorX& w, double alphaTilde,
                              std::vector<double>& lambda, Matrix3X& p, const SweepPlan& plan) {
    Invoke<decltype(projectDistanceSweepXpbd)>::call(submissionProcess(), remote::k_projectDistanceSweepXpbd, "projectDistanceSweepXpbd", links, w, alphaTilde, lambda, p, serialPlan(plan));
}

}  // namespace clothlab
