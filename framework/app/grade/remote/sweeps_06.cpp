// Stage 06's framework sweeps in the test process: when the stage's code is the submission's, the
// grader links these in place of the framework's own (sim/sweeps.cpp defines those weak), and a
// sweep crosses to the submission process whole, once per solver iteration (remote/functions.h).
#include "remote/functions.h"
#include "remote/peer.h"

namespace clothlab {

using remote::Invoke;
using remote::submissionProcess;

void projectCollisionSweep(const std::vector<CollisionConstraint>& contacts, const VectorX& w, double h, Matrix3X& p, int) {
    Invoke<decltype(projectCollisionSweep)>::call(submissionProcess(), remote::k_projectCollisionSweep, "projectCollisionSweep", contacts, w, h, p, 1);  // serial: the sandbox makes no threads
}

}  // namespace clothlab
