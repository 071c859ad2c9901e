#include "clothlab/sim/pbd.h"

#include <algorithm>
#include <cmath>

#include "clothlab/core/grid.h"
#include "clothlab/core/input_error.h"
#include "clothlab/core/topology.h"
#include "clothlab/exercise/04_distance.h"
#include "clothlab/sim/xpbd.h"
#ifdef CLOTHLAB_BATCHED_KERNELS
#include "bending_batched.h"  // solutions/kernels: not in the student copy
#endif

namespace clothlab {

void projectDistanceSweep(const std::vector<DistanceLink>& links, const VectorX& w, double k, Matrix3X& p) {
    for (const DistanceLink& L : links) {
        const DistanceCorrection c = projectDistanceConstraint(p.col(L.i), p.col(L.j), w[L.i], w[L.j], L.d, k);
        p.col(L.i) += c.dp1;
        p.col(L.j) += c.dp2;
    }
}

void projectBendingSweep(const std::vector<BendingStencil>& stencils, const VectorX& w, double k, Matrix3X& p) {
    for (const BendingStencil& s : stencils) {
        const BendingCorrection c = projectBendingConstraint(p.col(s.i1), p.col(s.i2), p.col(s.i3), p.col(s.i4),
                                                             w[s.i1], w[s.i2], w[s.i3], w[s.i4], s.phi0, k);
        p.col(s.i1) += c.dp1;
        p.col(s.i2) += c.dp2;
        p.col(s.i3) += c.dp3;
        p.col(s.i4) += c.dp4;
    }
}

PbdSimulation::PbdSimulation(const Scene& scene) : Simulation(scene) {
    const SolverSpec& sv = scene.solver;
    xpbd_ = sv.method == "xpbd";
    subDt_ = sv.dt / sv.substeps;
    if (scene.forces.damping > 1.0)
        throw InputError(scene.file, "forces.damping", "must be in [0, 1] for " + sv.method + " (k_damping of dampVelocities)");
    const bool batched = sv.bendingKernel == "batched" && scene.constraints.bending.enabled;
    if (batched && xpbd_)
        throw InputError(scene.file, "solver.bending_kernel", "\"batched\" is for method \"pbd\" (use \"exercise\" with xpbd)");
#ifndef CLOTHLAB_BATCHED_KERNELS
    if (batched)
        throw InputError(scene.file, "solver.bending_kernel",
                         "\"batched\" comes with solutions/kernels/, which this copy does not have (use \"exercise\")");
#endif
    state_ = makeGridState(scene.cloth);
    triangles_ = gridTriangles(scene.cloth.nx, scene.cloth.ny);
    edges_ = uniqueEdges(triangles_);
    P_.x = state_.x;
    P_.v = state_.v;
    P_.w = state_.w;
    P_.p = P_.x;

    // Only what the scene uses becomes a pass.
    if (scene.forces.gravity.squaredNorm() > 0.0) gravityPass_ = timer_.add("forces: gravity");
    if (scene.forces.wind.squaredNorm() > 0.0) windPass_ = timer_.add("forces: wind");
    stepPass_ = timer_.add(std::string(xpbd_ ? "xpbd" : "pbd") + ": damp, predict, update");
    if (!scene.colliders.empty()) generatePass_ = timer_.add("collisions: generate");
    if (scene.constraints.distance.enabled) {
        distancePass_ = timer_.add("constraints: distance");
        // Distance constraints along every mesh edge, in colour order (see colourOrder()).
        std::vector<Eigen::Vector4i> sets;
        for (const auto& e : edges_) sets.emplace_back(e[0], e[1], -1, -1);
        for (int k : colourOrder(sets, state_.size())) {
            const auto& e = edges_[static_cast<size_t>(k)];
            links_.push_back({e[0], e[1], (P_.x.col(e[0]) - P_.x.col(e[1])).norm()});
        }
        linkLambda_.assign(links_.size(), 0.0);
        if (!xpbd_) kDistance_ = iterationStiffness(scene.constraints.distance.stiffness, sv.iterations);
    }
    if (scene.constraints.bending.enabled) {
        bendingPass_ = timer_.add("constraints: bending");
        const std::vector<BendingStencil> stencils = bendingStencils(triangles_, P_.x);
        std::vector<Eigen::Vector4i> sets;
        for (const auto& b : stencils) sets.emplace_back(b.i1, b.i2, b.i3, b.i4);
        for (int k : colourOrder(sets, state_.size())) stencils_.push_back(stencils[static_cast<size_t>(k)]);
        bendLambda_.assign(stencils_.size(), 0.0);
        if (!xpbd_) kBending_ = iterationStiffness(scene.constraints.bending.stiffness, sv.iterations);
#ifdef CLOTHLAB_BATCHED_KERNELS
        if (batched) blocks_ = std::make_shared<const BendingBlocks>(bendingBlocks(stencils_));
#endif
    }
    if (!scene.colliders.empty()) {
        collisionPass_ = timer_.add("constraints: collision");
        velocityPass_ = timer_.add("collisions: velocity update");
    }
}

void PbdSimulation::addExternalForces(const Matrix3X& x, const Matrix3X& v, Matrix3X& f) {
    const auto timed = [&](int id, auto&& fn) {
        const double before = timer_.passes()[static_cast<size_t>(id)].seconds;
        timer_.run(id, fn);
        nested_ += timer_.passes()[static_cast<size_t>(id)].seconds - before;
    };
    if (gravityPass_ >= 0)
        timed(gravityPass_, [&] {
            const Vec3 g = scene_.forces.gravity;
            for (int i = 0; i < f.cols(); ++i)
                if (P_.w[i] > 0.0) f.col(i) += g / P_.w[i];
        });
    if (windPass_ >= 0)
        timed(windPass_, [&] {
            // Per triangle: f = drag · A · ((v_wind − v̄)·n̂) n̂, split equally over its three particles.
            const Vec3 wind = scene_.forces.wind;
            const double drag = scene_.forces.drag;
            for (const auto& t : triangles_) {
                const Vec3 m = (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0]));
                const double twiceArea = m.norm();
                if (twiceArea < 1e-14) continue;
                const Vec3 n = m / twiceArea;
                const Vec3 vrel = wind - (v.col(t[0]) + v.col(t[1]) + v.col(t[2])) / 3.0;
                const Vec3 ft = drag * 0.5 * twiceArea * vrel.dot(n) * n / 3.0;
                for (int k = 0; k < 3; ++k) f.col(t[k]) += ft;
            }
        });
}

void PbdSimulation::generateCollisions(const Matrix3X& x, const Matrix3X& p) {
    const double before = timer_.passes()[static_cast<size_t>(generatePass_)].seconds;
    timer_.run(generatePass_, [&] {
        contacts_.clear();
        const double h = scene_.solver.thickness;
        CollisionConstraint c;
        for (int i = 0; i < x.cols(); ++i) {
            if (P_.w[i] <= 0.0) continue;
            for (const Collider& col : scene_.colliders) {
                const bool hit = col.type == Collider::Type::Plane
                                     ? generatePlaneConstraint(i, x.col(i), p.col(i), col, h, subDt_, &c)
                                     : generateSphereConstraint(i, x.col(i), p.col(i), col, h, subDt_, &c);
                if (hit) contacts_.push_back(c);
            }
        }
    });
    nested_ += timer_.passes()[static_cast<size_t>(generatePass_)].seconds - before;
}

void PbdSimulation::projectAll(Matrix3X& p) {
    const VectorX& w = P_.w;
    auto timed = [&](int id, auto&& fn) {
        const double before = timer_.passes()[static_cast<size_t>(id)].seconds;
        timer_.run(id, fn);
        nested_ += timer_.passes()[static_cast<size_t>(id)].seconds - before;
    };
    const double inv2 = 1.0 / (subDt_ * subDt_);
    if (distancePass_ >= 0)
        timed(distancePass_, [&] {
            if (!xpbd_) return projectDistanceSweep(links_, w, kDistance_, p);
            const double at = scene_.constraints.distance.compliance * inv2;
            for (size_t k = 0; k < links_.size(); ++k) {
                const DistanceLink& L = links_[k];
                const auto c = projectDistanceXpbd(p.col(L.i), p.col(L.j), w[L.i], w[L.j], L.d, at, linkLambda_[k]);
                p.col(L.i) += c.dp1;
                p.col(L.j) += c.dp2;
            }
        });
    if (bendingPass_ >= 0)
        timed(bendingPass_, [&] {
#ifdef CLOTHLAB_BATCHED_KERNELS
            if (blocks_) return projectBendingBlocks(*blocks_, w, kBending_, p);
#endif
            if (!xpbd_) return projectBendingSweep(stencils_, w, kBending_, p);
            const double at = scene_.constraints.bending.compliance * inv2;
            for (size_t k = 0; k < stencils_.size(); ++k) {
                const BendingStencil& s = stencils_[k];
                const auto c = projectBendingXpbd(p.col(s.i1), p.col(s.i2), p.col(s.i3), p.col(s.i4), w[s.i1], w[s.i2],
                                                  w[s.i3], w[s.i4], s.phi0, at, bendLambda_[k]);
                p.col(s.i1) += c.dp1;
                p.col(s.i2) += c.dp2;
                p.col(s.i3) += c.dp3;
                p.col(s.i4) += c.dp4;
            }
        });
    if (collisionPass_ >= 0)
        timed(collisionPass_, [&] {
            const double h = scene_.solver.thickness;
            for (const CollisionConstraint& c : contacts_) p.col(c.i) += projectCollisionConstraint(p.col(c.i), w[c.i], h, c);
        });
}

void PbdSimulation::step() {
    PbdCallbacks cb;
    cb.externalForces = [this](const Matrix3X& x, const Matrix3X& v, Matrix3X& f) { addExternalForces(x, v, f); };
    if (generatePass_ >= 0) {
        cb.generateCollisionConstraints = [this](const Matrix3X& x, const Matrix3X& p) { generateCollisions(x, p); };
        cb.velocityUpdate = [this](const Matrix3X&, Matrix3X& v) {
            const double before = timer_.passes()[static_cast<size_t>(velocityPass_)].seconds;
            timer_.run(velocityPass_, [&] { velocityUpdate(v, contacts_); });
            nested_ += timer_.passes()[static_cast<size_t>(velocityPass_)].seconds - before;
        };
    }
    if (distancePass_ >= 0 || bendingPass_ >= 0 || collisionPass_ >= 0)
        cb.projectConstraints = [this](Matrix3X& p) { projectAll(p); };
    const SolverSpec& sv = scene_.solver;
    P_.x = state_.x;  // the state may have been changed from outside (dragging a particle, a test)
    P_.v = state_.v;
    P_.w = state_.w;
    for (int s = 0; s < sv.substeps; ++s) {
        std::fill(linkLambda_.begin(), linkLambda_.end(), 0.0);  // XPBD: λ = 0 at the start of every (sub)step
        std::fill(bendLambda_.begin(), bendLambda_.end(), 0.0);
        nested_ = 0.0;
        timer_.run(stepPass_, [&] { pbdStep(P_, cb, scene_.forces.damping, sv.iterations, subDt_); });
        timer_.subtract(stepPass_, nested_);
    }
    updateState();
    state_.t += sv.dt;
}

void PbdSimulation::updateState() {
    state_.x = P_.x;
    state_.v = P_.v;
}

double PbdSimulation::maxStrain() const {
    double m = 0.0;
    for (const auto& L : links_)
        if (L.d > 0.0) m = std::max(m, std::abs((state_.x.col(L.i) - state_.x.col(L.j)).norm() - L.d) / L.d);
    return m;
}

double PbdSimulation::rmsStrain() const {
    if (links_.empty()) return 0.0;
    double s = 0.0;
    for (const auto& L : links_) {
        if (L.d <= 0.0) continue;
        const double e = ((state_.x.col(L.i) - state_.x.col(L.j)).norm() - L.d) / L.d;
        s += e * e;
    }
    return std::sqrt(s / static_cast<double>(links_.size()));
}

double PbdSimulation::rmsBendingError() const {
    if (stencils_.empty()) return 0.0;
    double s = 0.0;
    for (const auto& b : stencils_) {
        const BendingGradients g =
            bendingGradients(state_.x.col(b.i1), state_.x.col(b.i2), state_.x.col(b.i3), state_.x.col(b.i4));
        const double e = (g.valid ? std::acos(g.d) : M_PI) - b.phi0;
        s += e * e;
    }
    return std::sqrt(s / static_cast<double>(stencils_.size()));
}

double PbdSimulation::maxPenetration() const {
    const double h = scene_.solver.thickness;
    double m = 0.0;
    for (int i = 0; i < state_.size(); ++i)
        for (const Collider& c : scene_.colliders) {
            const Vec3 x = state_.x.col(i);
            const double dist = c.type == Collider::Type::Plane ? (x - c.point).dot(c.normal)
                                                                : (x - c.point).norm() - c.radius;
            m = std::max(m, h - dist);
        }
    return m;
}

double PbdSimulation::energy() const {
    double e = 0.0;
    for (int i = 0; i < state_.size(); ++i) {
        if (state_.w[i] <= 0.0) continue;
        const double m = 1.0 / state_.w[i];
        e += 0.5 * m * state_.v.col(i).squaredNorm() - m * scene_.forces.gravity.dot(state_.x.col(i));
    }
    return e;
}

std::vector<Metric> PbdSimulation::metrics() const {
    std::vector<Metric> m = {{"energy", energy(), "J"}};
    if (!links_.empty()) {
        m.push_back({"max_strain", maxStrain(), "1"});
        m.push_back({"rms_strain", rmsStrain(), "1"});
    }
    if (!stencils_.empty()) m.push_back({"rms_bending_error", rmsBendingError(), "rad"});
    if (!scene_.colliders.empty()) m.push_back({"max_penetration", std::max(0.0, maxPenetration()), "m"});
    return m;
}

}  // namespace clothlab
