// Registers the batched kernels as the solver's constraint kernel "batched" (solver.kernel:
// "batched"; see framework/include/clothlab/sim/extensions.h): distance_batched.h for the distance
// links, bending_batched.h for the bending stencils.
// Linked into the programs by cmake/extensions.cmake, only where solutions/kernels/ exists.
#include <memory>
#include <utility>

#include "bending_batched.h"
#include "clothlab/sim/extensions.h"
#include "distance_batched.h"

namespace clothlab {
namespace {

// The sweep over `data` (built once, shared by both forms): pbd(data, w, k, p) and
// xpbd(data, w, α̃, λ, p).
template <class Data, class Pbd, class Xpbd>
ConstraintSweep sweepOver(Data data, Pbd pbd, Xpbd xpbd) {
    auto shared = std::make_shared<const Data>(std::move(data));
    ConstraintSweep sweep;
    sweep.pbd = [shared, pbd](const VectorX& w, double k, Matrix3X& p) { pbd(*shared, w, k, p); };
    sweep.xpbd = [shared, xpbd](const VectorX& w, double alphaTilde, std::vector<double>& lambda, Matrix3X& p) {
        xpbd(*shared, w, alphaTilde, lambda, p);
    };
    return sweep;
}

const bool registered = [] {
    SweepKernel kernel;
    kernel.distance = [](const std::vector<DistanceLink>& links, const SweepPlan& plan) {
        return sweepOver(distanceArrays(links, plan), projectDistanceArrays, projectDistanceArraysXpbd);
    };
    kernel.bending = [](const std::vector<BendingStencil>& stencils, const SweepPlan& plan) {
        // lambdas, not the functions' names: their last parameter (the loop) has a default
        return sweepOver(
            bendingBlocks(stencils, plan),
            [](const BendingBlocks& b, const VectorX& w, double k, Matrix3X& p) { projectBendingBlocks(b, w, k, p); },
            [](const BendingBlocks& b, const VectorX& w, double alphaTilde, std::vector<double>& lambda, Matrix3X& p) {
                projectBendingBlocksXpbd(b, w, alphaTilde, lambda, p);
            });
    };
    registerSweepKernel("batched", kernel);
    return true;
}();

}  // namespace
}  // namespace clothlab
