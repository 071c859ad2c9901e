// Stage 07's framework sweeps in the test process: sent whole to the submission process when the
// stage's code is the submission's (remote/functions.h: 901–906; the grader links with --wrap).
#include "remote/functions.h"
#include "remote/peer.h"

namespace clothlab {

using remote::Invoke;
using remote::submissionProcess;

void wrappedSelfCollisionSweep(const std::vector<DistanceLink>& pairs, const Matrix3X& x, const VectorX& w, double mu, Matrix3X& p) __asm__("__wrap__ZN8clothlab25projectSelfCollisionSweepERKSt6vectorINS_12DistanceLinkESaIS1_EERKN5Eigen6MatrixIdLi3ELin1ELi0ELi3ELin1EEERKNS7_IdLin1ELi1ELi0ELin1ELi1EEEdRS8_");
void wrappedSelfCollisionSweep(const std::vector<DistanceLink>& pairs, const Matrix3X& x, const VectorX& w, double mu, Matrix3X& p) {
    Invoke<decltype(projectSelfCollisionSweep)>::call(submissionProcess(), remote::k_projectSelfCollisionSweep, "projectSelfCollisionSweep",
                                                      pairs, x, w, mu, p);
}

}  // namespace clothlab
