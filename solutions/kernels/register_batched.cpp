// Registers the batched kernels as the solver's constraint kernel "batched" (solver.kernel:
// "batched"; see framework/include/clothlab/sim/kernel_registry.h): distance_batched.h for the distance
// links, bending_batched.h for the bending stencils, neighbour_pairs_batched.h for the self-collision pairs.
// Linked into the programs by cmake/extensions.cmake, only where solutions/kernels/ exists.
#include "bending_batched.h"
#include "clothlab/sim/kernel_registry.h"
#include "distance_batched.h"
#include "neighbour_pairs_batched.h"

namespace clothlab {
namespace {

const bool registered = [] {
    SweepKernel kernel;
    kernel.distance = [](const std::vector<DistanceLink>& links, const SweepPlan& plan) {  // sweepOver(): kernel_registry.h
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
    kernel.neighbourPairs = neighbourPairsBatched;
    registerSweepKernel("batched", kernel);
    return true;
}();

}  // namespace
}  // namespace clothlab
