#include "clothlab/sim/kernel_registry.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "clothlab/sim/sweeps.h"

namespace clothlab {
namespace {
/// Registered kernels by name (a function-local static, so registering from a static initialiser
/// of another file is safe).
std::map<std::string, SweepKernel>& registry() {
    static std::map<std::string, SweepKernel> kernels;
    return kernels;
}

/// The kernel called `name`, null for "exercise".
const SweepKernel* findKernel(const std::string& name) {
    if (name == "exercise") return nullptr;
    const auto it = registry().find(name);
    if (it == registry().end()) throw std::out_of_range("no constraint kernel \"" + name + "\" is registered");
    return &it->second;
}

/// Kernel `name`'s sweep over `items` if it has a factory for them, else the exercise's sweeps `pbd`
/// and `xpbd` (sim/sweeps.h) over them.
template <class Item, class Factory, class Pbd, class Xpbd>
ConstraintSweep makeSweep(const std::string& name, Factory SweepKernel::*factory, const std::vector<Item>& items,
                          const SweepPlan& plan, Pbd* pbd, Xpbd* xpbd) {
    if (const SweepKernel* kernel = findKernel(name); kernel && kernel->*factory) return (kernel->*factory)(items, plan);
    using Listed = std::pair<std::vector<Item>, SweepPlan>;  // the constraints and their plan
    return sweepOver(
        Listed(items, plan),
        [pbd](const Listed& c, const VectorX& w, double k, Matrix3X& p) { pbd(c.first, w, k, p, c.second); },
        [xpbd](const Listed& c, const VectorX& w, double alphaTilde, std::vector<double>& lambda, Matrix3X& p) {
            xpbd(c.first, w, alphaTilde, lambda, p, c.second);
        });
}
}  // namespace

void registerSweepKernel(const std::string& name, SweepKernel kernel) { registry()[name] = std::move(kernel); }

std::vector<std::string> sweepKernelNames() {
    std::vector<std::string> names = {"exercise"};
    for (const auto& [name, kernel] : registry()) names.push_back(name);
    return names;
}

ConstraintSweep makeDistanceSweep(const std::string& name, const std::vector<DistanceLink>& links, const SweepPlan& plan) {
    return makeSweep(name, &SweepKernel::distance, links, plan, projectDistanceSweep, projectDistanceSweepXpbd);
}

ConstraintSweep makeBendingSweep(const std::string& name, const std::vector<BendingStencil>& stencils, const SweepPlan& plan) {
    return makeSweep(name, &SweepKernel::bending, stencils, plan, projectBendingSweep, projectBendingSweepXpbd);
}

NeighbourSearch makeNeighbourSearch(const std::string& name) {
    if (const SweepKernel* kernel = findKernel(name); kernel && kernel->neighbourPairs) return kernel->neighbourPairs;
    return [](const Matrix3X& p, double d) {  // exercises 7.3 and 7.4
        return findNeighbourPairs(p, buildSpatialHash(p, d, 2 * std::max<int>(1, static_cast<int>(p.cols()))), d);
    };
}

}  // namespace clothlab
