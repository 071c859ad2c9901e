// Registers the batched kernels as the solver's constraint kernel "batched" (solver.kernel:
// "batched"; see framework/include/clothlab/sim/extensions.h): distance_batched.h for the distance
// links, bending_batched.h for the bending stencils.
// Linked into the programs by cmake/extensions.cmake, only where solutions/kernels/ exists.
#include <memory>

#include "bending_batched.h"
#include "clothlab/sim/extensions.h"
#include "distance_batched.h"

namespace clothlab {
namespace {

const bool registered = [] {
    SweepKernel kernel;
    kernel.distance = [](const std::vector<DistanceLink>& links, const SweepPlan& plan) -> ConstraintSweep {
        auto arrays = std::make_shared<const DistanceArrays>(distanceArrays(links, plan));
        ConstraintSweep sweep;
        sweep.pbd = [arrays](const VectorX& w, double k, Matrix3X& p) { projectDistanceArrays(*arrays, w, k, p); };
        sweep.xpbd = [arrays](const VectorX& w, double alphaTilde, std::vector<double>& lambda, Matrix3X& p) {
            projectDistanceArraysXpbd(*arrays, w, alphaTilde, lambda, p);
        };
        return sweep;
    };
    kernel.bending = [](const std::vector<BendingStencil>& stencils, const SweepPlan& plan) -> ConstraintSweep {
        auto blocks = std::make_shared<const BendingBlocks>(bendingBlocks(stencils, plan));
        ConstraintSweep sweep;
        sweep.pbd = [blocks](const VectorX& w, double k, Matrix3X& p) { projectBendingBlocks(*blocks, w, k, p); };
        sweep.xpbd = [blocks](const VectorX& w, double alphaTilde, std::vector<double>& lambda, Matrix3X& p) {
            projectBendingBlocksXpbd(*blocks, w, alphaTilde, lambda, p);
        };
        return sweep;
    };
    registerSweepKernel("batched", kernel);
    return true;
}();

}  // namespace
}  // namespace clothlab
