#include "clothlab/sim/mass_spring.h"

#include <cmath>

#include "clothlab/sim/forces.h"
#include "clothlab/sim/rk4.h"

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
    for (int i = 0; i < c.particles; ++i) {
        m.state.x.col(i) = c.anchor + i * c.l0 * c.direction;
        m.state.w[i] = i == 0 ? 0.0 : 1.0 / c.mass;
        if (i > 0) m.springs.push_back({i - 1, i, c.k, c.l0, c.kd, SpringType::Single});
    }
    return m;
}

std::optional<DampedOscillator> singleSpringAnalytic(const Scene& scene) {
    if (scene.model != "spring") return std::nullopt;
    const SingleSpringSpec& s = scene.spring;
    const Vec3 d = s.start - s.anchor;
    if (d.norm() < 1e-12 || s.k <= 0.0) return std::nullopt;
    const Vec3 u = d.normalized();
    const auto parallel = [&](const Vec3& a) { return a.cross(u).norm() <= 1e-12 * std::max(1.0, a.norm()); };
    if (!parallel(scene.forces.gravity) || !parallel(s.velocity)) return std::nullopt;
    DampedOscillator o;
    o.m = s.mass;
    o.k = s.k;
    o.c = s.kd + scene.forces.damping;
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
    if (f.gravity.squaredNorm() > 0.0)
        addForce("forces: gravity", [this, g = f.gravity](const Matrix3X&, const Matrix3X&, Matrix3X& out) {
            addGravityForces(state_.w, g, out);
        });
    if (f.damping > 0.0)
        addForce("forces: damping", [c = f.damping](const Matrix3X&, const Matrix3X& v, Matrix3X& out) {
            addVelocityDamping(v, c, out);
        });
    if (!springs_.empty())
        addForce("forces: springs", [this](const Matrix3X& x, const Matrix3X& v, Matrix3X& out) {
            addSpringForces(springs_, x, v, out);
        });
    integrate_pass_ = timer_.add("integrate: " + scene.solver.method);
    analytic_ = singleSpringAnalytic(scene);
    if (analytic_) {
        anchor_ = scene.spring.anchor;
        axis_ = (scene.spring.start - scene.spring.anchor).normalized();
    }
    initial_energy_ = energy();
}

void MassSpringSimulation::addForce(const std::string& name, ForceTerm term) {
    forces_.emplace_back(timer_.add(name), std::move(term));
}

void MassSpringSimulation::step() {
    double force_seconds = 0.0;
    const ForceField field = [&](const Matrix3X& x, const Matrix3X& v, Matrix3X& f) {
        f.setZero(3, x.cols());
        for (auto& [id, term] : forces_) {
            const double before = timer_.passes()[static_cast<size_t>(id)].seconds;
            timer_.run(id, [&] { term(x, v, f); });
            force_seconds += timer_.passes()[static_cast<size_t>(id)].seconds - before;
        }
    };
    const std::string& method = scene_.solver.method;
    const double dt = scene_.solver.dt;
    timer_.run(integrate_pass_, [&] {
        if (method == "explicit_euler") explicitEulerStep(state_.x, state_.v, state_.w, field, dt);
        else if (method == "symplectic_euler") symplecticEulerStep(state_.x, state_.v, state_.w, field, dt);
        else if (method == "velocity_verlet") velocityVerletStep(state_.x, state_.v, state_.w, field, dt);
        else rk4Step(state_.x, state_.v, state_.w, field, dt);
    });
    timer_.subtract(integrate_pass_, force_seconds);  // the report shows force passes separately
    state_.t += dt;
}

double MassSpringSimulation::energy() const {
    return kineticEnergy(state_.w, state_.v) + gravityEnergy(state_.w, state_.x, scene_.forces.gravity) +
           springEnergy(springs_, state_.x);
}

std::vector<Metric> MassSpringSimulation::metrics() const {
    const double e = energy();
    std::vector<Metric> m = {{"energy", e, "J"}, {"energy_drift", e - initial_energy_, "J"}};
    if (analytic_) {
        const Vec3 exact = anchor_ + analytic_->position(state_.t) * axis_;
        const double err = (state_.x.col(1) - exact).norm();
        max_error_ = std::max(max_error_, err);
        m.push_back({"error", err, "m"});
        m.push_back({"max_error", max_error_, "m"});
    }
    return m;
}

}  // namespace clothlab
