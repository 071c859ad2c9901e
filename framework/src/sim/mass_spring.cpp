#include "clothlab/sim/mass_spring.h"

#include <cmath>

#include <limits>

#include "clothlab/core/grid.h"
#include "clothlab/exercise/02_mfn.h"
#include "clothlab/sim/forces.h"
#include "clothlab/sim/provot.h"
#include "clothlab/sim/strain.h"

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

MassSpringModel makeCloth(const Scene& scene) {
    MassSpringModel m;
    m.state = makeGridState(scene.cloth);
    m.springs = makeClothSprings(m.state.x, scene.cloth.nx, scene.cloth.ny, scene.springs);
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
    if (scene.model == "cloth") {
        triangles_ = gridTriangles(scene.cloth.nx, scene.cloth.ny);
        if (f.gravity.squaredNorm() > 0.0 || f.damping > 0.0)  // stage 02, task 2.3
            addForce(f.damping > 0.0 ? "forces: gravity + damping" : "forces: gravity",
                     [this, g = f.gravity, c = f.damping](const Matrix3X&, const Matrix3X& v, Matrix3X& out) {
                         addClothExternalForces(state_.w, v, g, c, out);
                     });
        if (!springs_.empty())  // stage 02, task 2.2
            addForce("forces: springs", [this](const Matrix3X& x, const Matrix3X& v, Matrix3X& out) {
                addClothSpringForces(springs_, x, v, out);
            });
    } else {
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
    }
    integrate_pass_ = timer_.add("integrate: " + scene.solver.method);
    if (scene.provot.enabled && !springs_.empty()) provot_pass_ = timer_.add("provot: strain limit");
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
    // (1) F(x, v): the sum of all force passes, each timed on its own
    const ForceField field = [&](const Matrix3X& x, const Matrix3X& v, Matrix3X& f) {
        f.setZero(3, x.cols());
        for (auto& [id, term] : forces_) {
            const double before = timer_.passes()[static_cast<size_t>(id)].seconds;
            timer_.run(id, [&] { term(x, v, f); });
            force_seconds += timer_.passes()[static_cast<size_t>(id)].seconds - before;
        }
    };
    const double dt = scene_.solver.dt;
    // (2) one step of the chosen integrator
    timer_.run(integrate_pass_, [&] { integrate(field, dt); });
    timer_.subtract(integrate_pass_, force_seconds);  // the report shows force passes separately
    // (3) Provot: shorten springs stretched beyond (1 + tau) l0
    if (provot_pass_ >= 0)
        timer_.run(provot_pass_, [&] {
            applyProvotConstraint(springs_, state_.x, state_.v, state_.w, scene_.provot.max_strain, dt);
        });
    state_.t += dt;
}

void MassSpringSimulation::integrate(const ForceField& field, double dt) {
    const std::string& method = scene_.solver.method;
    State& s = state_;
    if (method == "explicit_euler") explicitEulerStep(s.x, s.v, s.w, field, dt);
    else if (method == "symplectic_euler") symplecticEulerStep(s.x, s.v, s.w, field, dt);
    else if (method == "velocity_verlet") velocityVerletStep(s.x, s.v, s.w, field, dt);
    else if (method == "rk4") rk4Step(s.x, s.v, s.w, field, dt, rk4_);
    else if (!implicit_.step(s.x, s.v, s.w, field, springs_, scene_.forces.damping, dt))
        s.x.setConstant(std::numeric_limits<double>::quiet_NaN());  // failed solve: runSimulation reports it
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
    if (scene_.model == "cloth") {  // super-elasticity
        const StrainStats strain = springStrain(springs_, state_.x);
        m.push_back({"max_strain", 100.0 * strain.max, "%"});
        m.push_back({"rms_strain", 100.0 * strain.rms, "%"});
    }
    return m;
}

}  // namespace clothlab
