#include "clothlab/sim/extensions.h"

#include <map>
#include <stdexcept>

#include "clothlab/sim/sweeps.h"

namespace clothlab {
namespace {
/// Registered sweeps by name (a function-local static, so registering from a static initialiser
/// of another file is safe).
std::map<std::string, BendingSweepFactory>& registry() {
    static std::map<std::string, BendingSweepFactory> sweeps;
    return sweeps;
}
}  // namespace

void registerBendingSweep(const std::string& name, BendingSweepFactory make) { registry()[name] = std::move(make); }

std::vector<std::string> bendingSweepNames() {
    std::vector<std::string> names = {"exercise"};
    for (const auto& [name, make] : registry()) names.push_back(name);
    return names;
}

BendingSweep makeBendingSweep(const std::string& name, const std::vector<BendingStencil>& stencils, const SweepPlan& plan) {
    if (name == "exercise") {
        BendingSweep sweep;
        sweep.pbd = [stencils, plan](const VectorX& w, double k, Matrix3X& p) { projectBendingSweep(stencils, w, k, p, plan); };
        sweep.xpbd = [stencils, plan](const VectorX& w, double alphaTilde, std::vector<double>& lambda, Matrix3X& p) {
            projectBendingSweepXpbd(stencils, w, alphaTilde, lambda, p, plan);
        };
        return sweep;
    }
    const auto it = registry().find(name);
    if (it == registry().end()) throw std::out_of_range("no bending sweep \"" + name + "\" is registered");
    return it->second(stencils, plan);
}

}  // namespace clothlab
