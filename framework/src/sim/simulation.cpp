#include "clothlab/sim/simulation.h"

#include "clothlab/core/input_error.h"
#include "clothlab/core/topology.h"
#include "clothlab/sim/energy.h"
#include "clothlab/sim/mass_spring.h"
#include "clothlab/sim/pbd.h"

namespace clothlab {

void Simulation::initMeasures() {
    strainEdges_ = scene_.model == Model::Cloth ? uniqueEdges(triangles_) : edges_;
    strainRest_.clear();
    for (const auto& e : strainEdges_) strainRest_.push_back((state().x.col(e[1]) - state().x.col(e[0])).norm());
    initialEnergy_ = energy();
}

double Simulation::energy() const {
    const State& s = state();
    return kineticEnergy(s.w, s.v) + gravityEnergy(s.w, s.x, scene_.forces.gravity) + elasticEnergy();
}

EdgeStrain Simulation::strain() const { return edgeStrain(strainEdges_, strainRest_, state().x); }

std::vector<Metric> Simulation::metrics() const {
    const double e = energy();
    std::vector<Metric> m = {{"energy", e, "J"}, {"energy_drift", e - initialEnergy_, "J"}};
    if (scene_.model != Model::Spring) {
        const EdgeStrain s = strain();
        m.push_back({"max_strain", s.max, "1"});
        m.push_back({"rms_strain", s.rms, "1"});
    }
    addMetrics(m);
    return m;
}

std::unique_ptr<Simulation> makeSimulation(const Scene& scene) {
    if (isPositionBased(scene.solver.method)) {
        if (scene.model == Model::Cloth) return std::make_unique<PbdSimulation>(scene);
        throw InputError(scene.file, "solver.method",
                         std::string("\"") + methodName(scene.solver.method) + "\" needs model \"cloth\"");
    }
    switch (scene.model) {
        case Model::Spring: return std::make_unique<MassSpringSimulation>(scene, makeSingleSpring(scene.spring));
        case Model::Chain: return std::make_unique<MassSpringSimulation>(scene, makeChain(scene.chain));
        case Model::Cloth: return std::make_unique<MassSpringSimulation>(scene, makeCloth(scene));
    }
    throw InputError(scene.file, "model", "unknown model");
}

}  // namespace clothlab
