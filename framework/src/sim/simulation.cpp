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
    pinned_.clear();
    for (int i = 0; i < state().size(); ++i)
        if (state().w[i] == 0.0) pinned_.push_back(i);
}

void Simulation::checkMomentum(const Matrix3X& before, const Matrix3X& p, int pass) {
    if (!momentumBy_.empty() || !pinned_.empty()) return;
    const VectorX& w = state().w;
    Vec3 created = Vec3::Zero();
    double moved = 0.0, size = 0.0;
    for (int i = 0; i < p.cols(); ++i) {
        if (w[i] == 0.0) return;  // pinned since (the app's drag): an infinite mass, no check
        const Vec3 dp = p.col(i) - before.col(i);
        created += dp / w[i];
        moved += dp.norm() / w[i];
        size += p.col(i).norm() / w[i];
    }
    if (created.norm() > 1e-6 * moved && created.norm() > 1e-12 * size) {
        momentumBy_ = timer_.passes()[static_cast<size_t>(pass)].name;
        momentumCreated_ = created.norm() / moved;
    }
}

void Simulation::checkPins(const Matrix3X& p, int pass) {
    if (!pinMovedBy_.empty()) return;
    const State& s = state();
    for (int i : pinned_)  // (still pinned: the app may release a pin)
        if (s.w[i] == 0.0 && (p.col(i) - s.x.col(i)).squaredNorm() > 0.0) {
            pinMovedBy_ = timer_.passes()[static_cast<size_t>(pass)].name;
            return;
        }
}

void Simulation::noteBlowUp(const Matrix3X& q, int pass) {
    if (!q.allFinite() || (q.size() > 0 && q.colwise().norm().maxCoeff() >= blowUpBound_))
        blowUpBy_ = timer_.passes()[static_cast<size_t>(pass)].name;
}

std::string Simulation::blowUpBy(const State& before, double bound) {
    state() = before;
    blowUpBy_.clear();
    blowUpBound_ = bound;
    try {
        step();
    } catch (const std::exception&) {  // a solver failure names no pass
    }
    blowUpBound_ = 0.0;
    return blowUpBy_;
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
