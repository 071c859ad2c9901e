#include "clothlab/sim/simulation.h"

#include "clothlab/core/input_error.h"
#include "clothlab/sim/mass_spring.h"
#include "clothlab/sim/pbd.h"

namespace clothlab {

std::unique_ptr<Simulation> makeSimulation(const Scene& scene) {
    const std::string& method = scene.solver.method;
    const bool explicit_method = method == "explicit_euler" || method == "symplectic_euler" ||
                                 method == "velocity_verlet" || method == "rk4";
    const bool force_based = explicit_method || method == "implicit_euler";
    if (force_based && scene.model == "spring")
        return std::make_unique<MassSpringSimulation>(scene, makeSingleSpring(scene.spring));
    if (force_based && scene.model == "chain")
        return std::make_unique<MassSpringSimulation>(scene, makeChain(scene.chain));
    if (force_based && scene.model == "cloth")
        return std::make_unique<MassSpringSimulation>(scene, makeCloth(scene));
    if ((method == "pbd" || method == "xpbd") && scene.model == "cloth") return std::make_unique<PbdSimulation>(scene);
    throw InputError(scene.file, "solver.method",
                     "\"" + method + "\" on model \"" + scene.model + "\" is not available in this build");
}

}  // namespace clothlab
