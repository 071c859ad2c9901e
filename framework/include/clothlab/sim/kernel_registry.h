/// @file kernel_registry.h
/// @brief The one place where faster code plugs into the solver: registered constraint kernels.
///
/// The solver's default constraint passes are projectDistanceSweep() and projectBendingSweep():
/// exercises 4.3 and 5.2 once per constraint, in the order the solver chose (the student's or the
/// reference code); its self-collision pairs are exercises 7.3 and 7.4. A faster kernel with the same
/// result (vectorised sweeps, say) registers itself here under a name; a scene selects it with
/// `solver.kernel`. The framework never names such a kernel: the instructor build links it
/// (cmake/extensions.cmake), the student copy does not, and there only "exercise" is allowed.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "clothlab/exercise/05_bending.h"
#include "clothlab/exercise/07_self_collision.h"
#include "clothlab/sim/sweeps.h"

namespace clothlab {

/// One Gauss–Seidel sweep over a fixed list of constraints (distance links or bending stencils;
/// lines (9)–(10) of the PBD loop), in its PBD and its XPBD form. Both move the predicted positions
/// p (3 x N, m) given the inverse masses w (N, 1/kg).
struct ConstraintSweep {
    /// PBD, with the per-iteration stiffness k' in [0, 1]: the result of projectDistanceSweep() or
    /// projectBendingSweep().
    std::function<void(const VectorX& w, double k, Matrix3X& p)> pbd;
    /// XPBD, with α̃ = α/Δt² and one multiplier λ per constraint (updated): the result of
    /// projectDistanceSweepXpbd() or projectBendingSweepXpbd().
    std::function<void(const VectorX& w, double alphaTilde, std::vector<double>& lambda, Matrix3X& p)> xpbd;
};

/// The sweep over `data`, which is built once and shared by both forms (a kernel's precomputed arrays,
/// say): ConstraintSweep::pbd calls pbd(data, w, k, p) and ConstraintSweep::xpbd calls
/// xpbd(data, w, α̃, λ, p).
/// @param data  what both forms sweep over (moved into shared storage)
/// @param pbd   callable (const Data&, const VectorX& w, double k, Matrix3X& p)
/// @param xpbd  callable (const Data&, const VectorX& w, double alphaTilde, std::vector<double>& lambda, Matrix3X& p)
/// @return      the sweep
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

/// A search for the self-collision pairs (stage 07): every pair of particles closer than d, each once
/// as (i, j) with i < j, in any order, given the positions p (3 x N, m) and d (m).
using NeighbourSearch = std::function<std::vector<ParticlePair>(const Matrix3X& p, double d)>;

/// A kernel: what makes its sweeps for a list of constraints, projected in the given order, with
/// their colour groups and threads (a factory may precompute whatever it needs from them once), and
/// its search for the self-collision pairs. The result must not depend on the number of threads. An
/// empty member leaves that part to the exercises.
struct SweepKernel {
    std::function<ConstraintSweep(const std::vector<DistanceLink>& links, const SweepPlan& plan)> distance;  ///< distance links
    std::function<ConstraintSweep(const std::vector<BendingStencil>& stencils, const SweepPlan& plan)> bending;  ///< bending stencils
    NeighbourSearch neighbourPairs;  ///< the self-collision pairs (exercises 7.3 and 7.4's result)
};

/// Registers a kernel under `name` (call once, e.g. from a static initialiser of the kernel's file).
/// @param name    the value of `solver.kernel` that selects it; not "exercise"
/// @param kernel  its sweep factories
void registerSweepKernel(const std::string& name, SweepKernel kernel);

/// "exercise" (exercises 4.3 and 5.2 per constraint, always there) followed by every registered name.
std::vector<std::string> sweepKernelNames();

/// The distance sweep of kernel `name` over `links`: for "exercise" (or a kernel without a distance
/// factory) projectDistanceSweep() and projectDistanceSweepXpbd() over them.
/// @param name   "exercise" or a registered name
/// @param links  the links in projection order
/// @param plan   their colour groups (sweepPlan()) and the threads
/// @return       the sweep
/// @throws std::out_of_range for a name nobody registered (scene loading rejects those first)
ConstraintSweep makeDistanceSweep(const std::string& name, const std::vector<DistanceLink>& links, const SweepPlan& plan);

/// The bending sweep of kernel `name` over `stencils`: for "exercise" (or a kernel without a bending
/// factory) projectBendingSweep() and projectBendingSweepXpbd() over them.
/// @param name      "exercise" or a registered name
/// @param stencils  the stencils in projection order
/// @param plan      their colour groups (sweepPlan()) and the threads
/// @return          the sweep
/// @throws std::out_of_range for a name nobody registered (scene loading rejects those first)
ConstraintSweep makeBendingSweep(const std::string& name, const std::vector<BendingStencil>& stencils, const SweepPlan& plan);

/// The self-collision pair search of kernel `name`: for "exercise" (or a kernel without one)
/// exercises 7.3 and 7.4, findNeighbourPairs(p, buildSpatialHash(p, d, T), d) with T = 2N buckets.
/// @param name  "exercise" or a registered name
/// @return      the search
/// @throws std::out_of_range for a name nobody registered (scene loading rejects those first)
NeighbourSearch makeNeighbourSearch(const std::string& name);

}  // namespace clothlab
