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
        return [blocks](const VectorX& w, double k, Matrix3X& p) { projectBendingBlocks(*blocks, w, k, p); };
    });
    return true;
}();

}  // namespace
}  // namespace clothlab
