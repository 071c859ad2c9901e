// Registers the batched bending kernel as the solver's bending sweep "batched"
// (solver.bending_kernel: "batched"; see framework/include/clothlab/sim/extensions.h).
// Linked into the programs by cmake/extensions.cmake, only where solutions/kernels/ exists.
#include <memory>

#include "bending_batched.h"
#include "clothlab/sim/extensions.h"

namespace clothlab {
namespace {

const bool registered = [] {
    registerBendingSweep("batched", [](const std::vector<BendingStencil>& stencils, const SweepPlan& plan) -> BendingSweep {
        auto blocks = std::make_shared<const BendingBlocks>(bendingBlocks(stencils, plan));
        BendingSweep sweep;
        sweep.pbd = [blocks](const VectorX& w, double k, Matrix3X& p) { projectBendingBlocks(*blocks, w, k, p); };
        sweep.xpbd = [blocks](const VectorX& w, double alphaTilde, std::vector<double>& lambda, Matrix3X& p) {
            projectBendingBlocksXpbd(*blocks, w, alphaTilde, lambda, p);
        };
        return sweep;
    });
    return true;
}();

}  // namespace
}  // namespace clothlab
