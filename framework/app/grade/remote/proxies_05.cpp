// Stage 05 in the test process: each function forwards to the submission process (remote/peer.h).
#include "remote/functions.h"
#include "remote/peer.h"

namespace clothlab {

using remote::Invoke;
using remote::submissionProcess;

BendingGradients bendingGradients(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
    return Invoke<decltype(bendingGradients)>::call(submissionProcess(), remote::k_bendingGradients, "bendingGradients",
                                                    p1, p2, p3, p4);
}

BendingCorrection projectBendingConstraint(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4, double w1,
                                           double w2, double w3, double w4, double phi0, double k) {
    return Invoke<decltype(projectBendingConstraint)>::call(submissionProcess(), remote::k_projectBendingConstraint,
                                                            "projectBendingConstraint", p1, p2, p3, p4, w1, w2, w3, w4,
                                                            phi0, k);
}

std::vector<BendingStencil> bendingStencils(const std::vector<Eigen::Vector3i>& triangles, const Matrix3X& x) {
    std::vector<BendingStencil> stencils = Invoke<decltype(bendingStencils)>::call(
        submissionProcess(), remote::k_bendingStencils, "bendingStencils", triangles, x);
    // The framework indexes particles with these: an index outside 0..N-1 is refused here.
    const auto check = [&](int particle) {
        if (particle < 0 || particle >= x.cols())
            throw std::out_of_range("bendingStencils returned a stencil with particle " + std::to_string(particle) +
                                    ", but there are " + std::to_string(x.cols()) + " (0.." + std::to_string(x.cols() - 1) + ")");
    };
    for (const BendingStencil& stencil : stencils) {
        check(stencil.i1);
        check(stencil.i2);
        check(stencil.i3);
        check(stencil.i4);
    }
    return stencils;
}

// The framework's sweeps over this stage's constraints, sent whole (remote/functions.h: 901–905).

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
