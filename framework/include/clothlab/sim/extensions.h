/// @file extensions.h
/// @brief The one place where faster code plugs into the solver: registered bending sweeps.
///
/// The solver's default bending pass is projectBendingSweep(): exercise 5.2 per stencil, in the
/// order the solver chose (the student's or the reference code). A faster sweep with the same
/// result (a vectorised kernel, say) registers itself here under a name; a scene selects it with
/// `solver.bending_kernel`. The framework never names such a kernel: the instructor build links it
/// (cmake/extensions.cmake), the student copy does not, and there only "exercise" is allowed.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "clothlab/exercise/05_bending.h"
#include "clothlab/sim/sweeps.h"

namespace clothlab {

/// One Gauss–Seidel sweep over a fixed list of bending stencils (lines (9)–(10) of the PBD loop,
/// bending part), in its PBD and its XPBD form. Both move the predicted positions p (3 x N, m) given
/// the inverse masses w (N, 1/kg).
struct BendingSweep {
    /// PBD, with the per-iteration stiffness k' in [0, 1]: the result of projectBendingSweep().
    std::function<void(const VectorX& w, double k, Matrix3X& p)> pbd;
    /// XPBD, with α̃ = α/Δt² and one multiplier λ per stencil (updated): the result of projectBendingSweepXpbd().
    std::function<void(const VectorX& w, double alphaTilde, std::vector<double>& lambda, Matrix3X& p)> xpbd;
};

/// Makes a sweep for the given stencils, projected in the given order, with their colour groups and
/// threads (it may precompute whatever it needs from them once). The result must not depend on the
/// number of threads.
using BendingSweepFactory = std::function<BendingSweep(const std::vector<BendingStencil>& stencils, const SweepPlan& plan)>;

/// Registers a sweep under `name` (call once, e.g. from a static initialiser of the kernel's file).
/// @param name  the value of `solver.bending_kernel` that selects it; not "exercise"
/// @param make  builds the sweep for a list of stencils
void registerBendingSweep(const std::string& name, BendingSweepFactory make);

/// "exercise" (exercise 5.2 per stencil, always there) followed by every registered name.
std::vector<std::string> bendingSweepNames();

/// The sweep called `name` over `stencils`: "exercise" gives projectBendingSweep() and
/// projectBendingSweepXpbd() over them.
/// @param name      "exercise" or a registered name
/// @param stencils  the stencils in projection order
/// @param plan      their colour groups (sweepPlan()) and the threads
/// @return          the sweep
/// @throws std::out_of_range for a name nobody registered (scene loading rejects those first)
BendingSweep makeBendingSweep(const std::string& name, const std::vector<BendingStencil>& stencils, const SweepPlan& plan);

}  // namespace clothlab
