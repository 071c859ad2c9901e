// Stage 07's framework sweeps in the test process: when the stage's code is the submission's, the
// grader links these in place of the framework's own (sim/sweeps.cpp defines those weak), and a
// sweep crosses to the submission process whole, once per solver iteration (remote/functions.h).
#include "remote/functions.h"
#include "remote/peer.h"

namespace clothlab {

using remote::Invoke;
using remote::submissionProcess;

void projectSelfCollisionSweep(const std::vector<DistanceLink>& pairs, const Matrix3X& x, const VectorX& w, double mu, Matrix3X& p) {
    Invoke<decltype(projectSelfCollisionSweep)>::call(submissionProcess(), remote::k_projectSelfCollisionSweep, "projectSelfCollisionSweep",
                                                      pairs, x, w, mu, p);
}

}  // namespace clothlab
