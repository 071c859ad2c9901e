#include "clothlab/sim/mass_spring.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "clothlab/core/grid.h"
#include "clothlab/core/topology.h"
#include "clothlab/exercise/02_mfn.h"
#include "clothlab/sim/energy.h"
#include "clothlab/sim/provot.h"
#include "clothlab/sim/sweeps.h"

namespace clothlab {

MassSpringModel makeSingleSpring(const SingleSpringSpec& s) {
    MassSpringModel m;
    m.state.resize(2);
    m.state.x.col(0) = s.anchor;
    m.state.w[0] = 0.0;  // the anchor is pinned
    m.state.x.col(1) = s.start;
    m.state.v.col(1) = s.velocity;
    m.state.w[1] = 1.0 / s.mass;
    m.springs.push_back({0, 1, s.k, s.l0, s.kd, SpringType::Single});
    return m;
}

MassSpringModel makeChain(const ChainSpec& c) {
    MassSpringModel m;
    m.state.resize(c.particles);
    Vec3 apex = c.anchor;  // with an end: the V's lowest point
    const double half = 0.5 * (c.particles - 1) * c.l0;
    if (c.end) {
        const Vec3 span = *c.end - c.anchor, u = span.normalized();
        const auto across = [&](const Vec3& dir) { return Vec3(dir - dir.dot(u) * u); };  // dir without its part along u
        Vec3 down = across(Vec3(0, -1, 0));
        if (down.norm() < 1e-9) down = across(Vec3(-1, 0, 0));
        apex = c.anchor + 0.5 * span + down.normalized() * std::sqrt(std::max(0.0, half * half - 0.25 * span.squaredNorm()));
    }
    for (int i = 0; i < c.particles; ++i) {
        const double s = i * c.l0;
        m.state.x.col(i) = !c.end ? Vec3(c.anchor + s * c.direction)
                           : s <= half ? Vec3(c.anchor + s / half * (apex - c.anchor))
                                       : Vec3(apex + (s - half) / half * (*c.end - apex));
        m.state.w[i] = i == 0 || (c.end && i == c.particles - 1) ? 0.0 : 1.0 / c.mass;
        if (i > 0) m.springs.push_back({i - 1, i, c.k, c.l0, c.kd, SpringType::Single});
    }
    return m;
}

MassSpringModel makeCloth(const Scene& scene) {
    MassSpringModel m;
    ClothGeometry cloth = makeClothGeometry(scene.cloth);
    m.state = std::move(cloth.state);
    m.springs = scene.cloth.meshData ? makeMeshSprings(m.state.x, cloth.triangles, scene.springs)
                                     : makeClothSprings(m.state.x, scene.cloth.nx, scene.cloth.ny, scene.springs);
    return m;
}

std::vector<Spring> makeMeshSprings(const Matrix3X& x, const std::vector<Eigen::Vector3i>& triangles, const ClothSprings& types) {
    std::vector<Spring> springs;
    const auto add = [&](int i, int j, const SpringGroup& g, SpringType type) {
        springs.push_back({i, j, g.k, (x.col(i) - x.col(j)).norm(), g.kd, type});
    };
    if (types.structural.enabled)
        for (const auto& e : uniqueEdges(triangles)) add(e[0], e[1], types.structural, SpringType::Structural);
    if (types.bending.enabled)
        for (const auto& e : oppositeVertices(triangles)) add(e[0], e[1], types.bending, SpringType::Bending);
    return springs;
}

std::optional<DampedOscillator> singleSpringAnalytic(const Scene& scene) {
    if (scene.model != Model::Spring) return std::nullopt;
    const SingleSpringSpec& s = scene.spring;
    const Vec3 d = s.start - s.anchor;
    if (d.norm() < 1e-12 || s.k <= 0.0) return std::nullopt;
    const Vec3 u = d.normalized();
    const auto parallel = [&](const Vec3& a) { return a.cross(u).norm() <= 1e-12 * std::max(1.0, a.norm()); };
    if (!parallel(scene.forces.gravity) || !parallel(s.velocity)) return std::nullopt;
    DampedOscillator o;
    o.m = s.mass;
    o.k = s.k;
    o.c = s.kd + scene.forces.air_damping;
    o.xi_eq = s.l0 + s.mass * scene.forces.gravity.dot(u) / s.k;
    o.xi0 = d.norm();
    o.u0 = s.velocity.dot(u);
    return o;
}

MassSpringSimulation::MassSpringSimulation(const Scene& scene, MassSpringModel model) : Simulation(scene) {
    state_ = std::move(model.state);
    springs_ = std::move(model.springs);
    for (const Spring& s : springs_) edges_.emplace_back(s.i, s.j);
    // Only the force terms the scene uses become passes.
    const ForcesSpec& f = scene.forces;
    const bool gravity = f.gravity.squaredNorm() > 0.0, air = f.air_damping > 0.0;
    const std::string externalName = gravity && air ? "forces: gravity + air damping" : gravity ? "forces: gravity" : "forces: air damping";
    if (scene.model == Model::Spring) {
        // Stage 01: particle 0 is the pinned anchor, so only particle 1 needs its force.
        const Spring spring = springs_.at(0);
        const double m = scene.spring.mass;
        if (gravity || air)
            addForce(externalName, [m, g = f.gravity, c = f.air_damping](const Matrix3X&, const Matrix3X& v, Matrix3X& out) {
                out.col(1) += m * g - c * v.col(1);
            });
        addForce("forces: spring", [spring](const Matrix3X& x, const Matrix3X&, Matrix3X& out) {
            out.col(1) += hookeForce(x.col(0), x.col(1), spring.k, spring.l0);  // exercise 1.1
        });
        if (spring.kd > 0.0)
            addForce("forces: spring damping", [spring](const Matrix3X& x, const Matrix3X& v, Matrix3X& out) {
                out.col(1) += springDampingForce(x.col(0), x.col(1), v.col(0), v.col(1), spring.kd);  // exercise 1.2
            });
    } else {
        // Stage 02: a chain or a cloth is a mass-spring network.
        if (scene.model == Model::Cloth) triangles_ = makeClothGeometry(scene.cloth).triangles;
        if (gravity || air)
            addForce(externalName, [this, g = f.gravity, c = f.air_damping](const Matrix3X&, const Matrix3X& v, Matrix3X& out) {
                addClothExternalForces(state_.w, v, g, c, out);  // exercise 2.3
            });
        if (!springs_.empty())
            addForce("forces: springs", [this](const Matrix3X& x, const Matrix3X& v, Matrix3X& out) {
                addClothSpringForces(springs_, x, v, out);  // exercise 2.2
            });
    }
    // F(x, v): the sum of all force passes; each is timed on its own, nested in the integrator's pass.
    field_ = [this](const Matrix3X& x, const Matrix3X& v, Matrix3X& out) {
        out.setZero(3, x.cols());
        for (auto& [id, term] : forces_) {
            auto timed = timer_.time(id);
            term(x, v, out);
        }
    };
    implicit_.setThreads(scene.solver.threads);  // 0: the faster of 1 and all cores (sim/team.h)
    integrate_pass_ = timer_.add(std::string("integrate: ") + methodName(scene.solver.method));
    if (scene.provot.enabled && !springs_.empty()) provot_pass_ = timer_.add("provot: strain limit");
    analytic_ = singleSpringAnalytic(scene);
    if (scene.model == Model::Chain && scene.chain.end && scene.forces.gravity.norm() > 0) {
        Catenary c{scene.chain.anchor, *scene.chain.end, -scene.forces.gravity.normalized(), (scene.chain.particles - 1) * scene.chain.l0};
        if (c.solve()) catenary_ = c;
    }
    if (analytic_) {
        anchor_ = scene.spring.anchor;
        axis_ = (scene.spring.start - scene.spring.anchor).normalized();
    }
    initMeasures();
    if (scene.model == Model::Cloth) movePins(state_, scene.cloth);  // pins given a position ("to") go there
}

void MassSpringSimulation::addForce(const std::string& name, ForceTerm term) {
    forces_.emplace_back(timer_.add(name), std::move(term));
}

void MassSpringSimulation::step() {
    const double dt = scene_.solver.dt;
    {  // (1) + (2): one step of the integrator on F(x, v); the force passes are booked on their own
        auto timed = timer_.time(integrate_pass_);
        integrate(dt);
    }
    if (provot_pass_ >= 0) {  // (3) Provot: shorten springs stretched beyond (1 + τ) l0
        auto timed = timer_.time(provot_pass_);
        applyProvotConstraint(springs_, state_.x, state_.v, state_.w, scene_.provot.max_strain, dt);
    }
    state_.t += dt;
    if (analytic_) max_error_ = std::max(max_error_, analyticError());
}

void MassSpringSimulation::integrate(double dt) {
    State& s = state_;
    switch (scene_.solver.method) {
        case Method::ExplicitEuler: return explicitEulerStep(s.x, s.v, s.w, field_, dt);      // exercise 1.3
        case Method::SymplecticEuler: return symplecticEulerStep(s.x, s.v, s.w, field_, dt);  // exercise 1.4
        case Method::VelocityVerlet: return velocityVerletStep(s.x, s.v, s.w, field_, dt);    // exercise 1.5
        case Method::Rk4: return rk4Step(s.x, s.v, s.w, field_, dt, rk4_);
        case Method::ImplicitEuler:
            if (!implicit_.step(s.x, s.v, s.w, field_, springs_, scene_.forces.air_damping, dt))
                throw SolverFailure("implicit Euler: the linear system (M - dt D - dt^2 K) dv = b has no finite solution");
            return;
        case Method::Pbd:
        case Method::Xpbd: break;
    }
    throw std::logic_error(std::string("MassSpringSimulation cannot step with ") + methodName(scene_.solver.method));
}

double MassSpringSimulation::elasticEnergy() const { return springEnergy(springs_, state_.x); }

double MassSpringSimulation::analyticError() const {
    if (!analytic_) return 0.0;
    const Vec3 exact = anchor_ + analytic_->position(state_.t) * axis_;
    return (state_.x.col(1) - exact).norm();
}

double MassSpringSimulation::catenaryError() const {
    if (!catenary_) return -1.0;
    double worst = 0.0;
    for (int i = 0; i < state_.size(); ++i) worst = std::max(worst, catenary_->distance(state_.x.col(i)));
    return worst / (catenary_->end - catenary_->start).norm();
}

void MassSpringSimulation::addMetrics(std::vector<Metric>& m) const {
    if (catenary_) m.push_back({"catenary_error", catenaryError(), "1"});
    if (scene_.solver.method == Method::ImplicitEuler) {  // how exactly the last step's linear system was solved
        m.push_back({"solve_residual", implicit_.residual(), "1"});
        m.push_back({"solve_iterations", static_cast<double>(implicit_.iterations()), "1"});
    }
    if (!analytic_) return;
    m.push_back({"error", analyticError(), "m"});
    m.push_back({"max_error", max_error_, "m"});
}

}  // namespace clothlab
