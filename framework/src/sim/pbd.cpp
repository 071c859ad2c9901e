#include "clothlab/sim/pbd.h"

#include <algorithm>
#include <cmath>

#include "clothlab/core/grid.h"
#include "clothlab/core/topology.h"
#include "clothlab/sim/colliders.h"
#include "clothlab/sim/xpbd.h"

namespace clothlab {

PbdSimulation::PbdSimulation(const Scene& scene) : Simulation(scene) {
    const SolverSpec& sv = scene.solver;
    xpbd_ = sv.method == Method::Xpbd;
    subDt_ = sv.dt / sv.substeps;
    team_ = AdaptiveTeam(sv.threads);  // solver.threads: N fixed, 0 (default) 1 or all cores, the faster (sim/team.h)
    threads_ = team_.most();
    // Lines (1)-(3): x_i, v_i, w_i of every particle (a grid or a mesh, at rest).
    ClothGeometry cloth = makeClothGeometry(scene.cloth);
    static_cast<State&>(P_) = std::move(cloth.state);
    triangles_ = std::move(cloth.triangles);
    edges_ = uniqueEdges(triangles_);

    // Only what the scene uses becomes a pass and a callback.
    const ForcesSpec& f = scene.forces;
    if (f.gravity.squaredNorm() > 0.0) gravityPass_ = timer_.add("forces: gravity");
    if (f.air_damping > 0.0) airPass_ = timer_.add("forces: air damping");
    if (f.wind.squaredNorm() > 0.0) windPass_ = timer_.add("forces: wind");
    if (gravityPass_ >= 0 || airPass_ >= 0 || windPass_ >= 0)
        callbacks_.externalForces = [this](const Matrix3X& x, const Matrix3X& v, Matrix3X& f) { addExternalForces(x, v, f); };
    stepPass_ = timer_.add(std::string(methodName(sv.method)) + ": damp, predict, update");
    if (scene.constraints.distance.enabled) {
        distancePass_ = timer_.add("constraints: distance");
        // One distance constraint along every mesh edge, in colour order (see colourOrder()).
        std::vector<Eigen::Vector4i> sets;
        for (const auto& e : edges_) sets.emplace_back(e[0], e[1], -1, -1);
        std::vector<Eigen::Vector4i> ordered;
        for (int k : colourOrder(sets, P_.size())) {
            const auto& e = edges_[static_cast<size_t>(k)];
            links_.push_back({e[0], e[1], (P_.x.col(e[0]) - P_.x.col(e[1])).norm()});
            ordered.push_back(sets[static_cast<size_t>(k)]);
        }
        linkPlan_ = sweepPlan(ordered, P_.size(), threads_);  // the colour groups, swept in parallel
        linkLambda_.assign(links_.size(), 0.0);
        if (!xpbd_) kDistance_ = iterationStiffness(scene.constraints.distance.stiffness, sv.iterations);
        distanceSweep_ = makeDistanceSweep(sv.kernel, links_, linkPlan_);  // "exercise": exercise 4.3
    }
    if (scene.constraints.bending.enabled) {
        bendingPass_ = timer_.add("constraints: bending");
        const std::vector<BendingStencil> stencils = bendingStencils(triangles_, P_.x);
        std::vector<Eigen::Vector4i> sets;
        for (const auto& b : stencils) sets.emplace_back(b.i1, b.i2, b.i3, b.i4);
        std::vector<Eigen::Vector4i> ordered;
        for (int k : colourOrder(sets, P_.size())) {
            stencils_.push_back(stencils[static_cast<size_t>(k)]);
            ordered.push_back(sets[static_cast<size_t>(k)]);
        }
        stencilPlan_ = sweepPlan(ordered, P_.size(), threads_);
        bendLambda_.assign(stencils_.size(), 0.0);
        if (!xpbd_) kBending_ = iterationStiffness(scene.constraints.bending.stiffness, sv.iterations);
        bendingSweep_ = makeBendingSweep(sv.kernel, stencils_, stencilPlan_);  // "exercise": exercise 5.2
    }
    if (!scene.colliders.empty()) {
        generatePass_ = timer_.add("collisions: generate");
        collisionPass_ = timer_.add("constraints: collision");
        velocityPass_ = timer_.add("collisions: velocity update");
        callbacks_.velocityUpdate = [this](const Matrix3X&, Matrix3X& v) {
            auto timed = timer_.time(velocityPass_);
            velocityUpdate(v, contacts_);  // exercise 6.4
        };
    }
    if (scene.self_collision.enabled) {  // stage 07: the cloth against itself
        hashPass_ = timer_.add("self-collision: hash and pairs");
        selfPass_ = timer_.add("constraints: self-collision");
        rest_ = P_.x;
    }
    if (generatePass_ >= 0 || hashPass_ >= 0)
        callbacks_.generateCollisionConstraints = [this](const Matrix3X& x, const Matrix3X& p) {
            if (generatePass_ >= 0) generateCollisions(x, p);
            if (hashPass_ >= 0) findSelfCollisions(p);
        };
    if (distancePass_ >= 0 || bendingPass_ >= 0 || collisionPass_ >= 0 || selfPass_ >= 0)
        callbacks_.projectConstraints = [this](Matrix3X& p) { projectConstraints(p); };
    initMeasures();
    movePins(P_, scene.cloth);  // pins given a position ("to") go there; the rest shape above stays
    P_.p = P_.x;
}

// Line (4) calls this once per frame; line (17) is its end.
void PbdSimulation::step() {
    const SolverSpec& sv = scene_.solver;
    auto unit = team_.unit();  // the sweeps' threads: solver.threads, or the faster, timed (sim/team.h)
    for (int s = 0; s < sv.substeps; ++s) {
        std::fill(linkLambda_.begin(), linkLambda_.end(), 0.0);  // XPBD: λ = 0 at the start of every (sub)step
        std::fill(bendLambda_.begin(), bendLambda_.end(), 0.0);
        auto timed = timer_.time(stepPass_);  // the passes called back from pbdStep() are booked on their own
        firstIteration_ = true;
        pbdStep(P_, callbacks_, scene_.pbd.damping, sv.iterations, subDt_);  // lines (5)-(16), exercise 3.3
    }
    P_.t += sv.dt;
}

void PbdSimulation::addExternalForces(const Matrix3X& x, const Matrix3X& v, Matrix3X& f) {
    const ForcesSpec& spec = scene_.forces;
    if (gravityPass_ >= 0) {  // m_i g
        auto timed = timer_.time(gravityPass_);
        for (int i = 0; i < f.cols(); ++i)
            if (P_.w[i] > 0.0) f.col(i) += spec.gravity / P_.w[i];
    }
    if (airPass_ >= 0) {  // −c v_i
        auto timed = timer_.time(airPass_);
        f -= spec.air_damping * v;
    }
    if (windPass_ >= 0) {  // per triangle: drag · A · ((v_wind − v̄)·n̂) n̂, split equally over its three particles
        auto timed = timer_.time(windPass_);
        for (const auto& t : triangles_) {
            const Vec3 m = (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0]));
            const double twiceArea = m.norm();
            if (twiceArea < 1e-14) continue;
            const Vec3 n = m / twiceArea;
            const Vec3 vrel = spec.wind - (v.col(t[0]) + v.col(t[1]) + v.col(t[2])) / 3.0;
            const Vec3 ft = spec.drag * 0.5 * twiceArea * vrel.dot(n) * n / 3.0;
            for (int k = 0; k < 3; ++k) f.col(t[k]) += ft;
        }
    }
}

void PbdSimulation::generateCollisions(const Matrix3X& x, const Matrix3X& p) {
    auto timed = timer_.time(generatePass_);
    contacts_.clear();
    const double h = scene_.solver.thickness;
    CollisionConstraint c;
    for (int i = 0; i < x.cols(); ++i) {
        if (P_.w[i] <= 0.0) continue;
        for (const Collider& col : scene_.colliders) {
            const Vec3 xi = x.col(i), pi = p.col(i);
            const bool hit =
                col.type == Collider::Type::Plane    ? generatePlaneConstraint(i, xi, pi, planeCollider(col), h, subDt_, &c)  // exercise 6.1
                : col.type == Collider::Type::Sphere ? generateSphereConstraint(i, xi, pi, sphereCollider(col), h, subDt_, &c)  // 6.2
                                                     : generateSolidConstraint(i, xi, pi, col, h, subDt_, &c);  // sim/colliders.h
            if (hit) contacts_.push_back(c);
        }
    }
}

void PbdSimulation::findSelfCollisions(const Matrix3X& p) {
    auto timed = timer_.time(hashPass_);
    const double h = scene_.self_collision.thickness;
    const int tableSize = 2 * std::max(1, P_.size());
    selfPairs_.clear();
    // Pairs within 1.25 h: a margin of h/4 for the motion during the iterations (exercises 7.3, 7.4).
    // Pairs closer than h at rest are the cloth's own neighbours, left to its distance constraints.
    const double query = 1.25 * h;
    for (const ParticlePair& q : findNeighbourPairs(p, buildSpatialHash(p, query, tableSize), query)) {
        if (P_.w[q.i] <= 0.0 && P_.w[q.j] <= 0.0) continue;
        if ((rest_.col(q.i) - rest_.col(q.j)).squaredNorm() < h * h) continue;
        selfPairs_.push_back({q.i, q.j, h});
    }
}

// Lines (9)-(11): each constraint type the scene uses, one pass each.
void PbdSimulation::projectConstraints(Matrix3X& p) {
    const VectorX& w = P_.w;
    const double dt2 = subDt_ * subDt_;
    checkPins(p, stepPass_);  // lines (5)-(7) predicted p
    if (distancePass_ >= 0)
        constraintPass(distancePass_, true, p, [&](Matrix3X& q) {
            if (xpbd_) distanceSweep_.xpbd(w, scene_.constraints.distance.compliance / dt2, linkLambda_, q);
            else distanceSweep_.pbd(w, kDistance_, q);
        });
    if (bendingPass_ >= 0)
        constraintPass(bendingPass_, true, p, [&](Matrix3X& q) {
            if (xpbd_) bendingSweep_.xpbd(w, scene_.constraints.bending.compliance / dt2, bendLambda_, q);
            else bendingSweep_.pbd(w, kBending_, q);
        });
    if (collisionPass_ >= 0)
        constraintPass(collisionPass_, false, p, [&](Matrix3X& q) { projectCollisionSweep(contacts_, w, scene_.solver.thickness, q, threads_); });
    if (selfPass_ >= 0)
        constraintPass(selfPass_, true, p, [&](Matrix3X& q) {
            projectSelfCollisionSweep(selfPairs_, P_.x, w, scene_.self_collision.friction, q);  // exercises 7.5, 7.6
        });
    firstIteration_ = false;
}

template <class Project>
void PbdSimulation::constraintPass(int pass, bool internal, Matrix3X& p, Project project) {
    const bool momentum = internal && firstIteration_ && !hasPins();
    if (momentum) before_ = p;
    {
        auto timed = timer_.time(pass);
        project(p);
    }
    checkPins(p, pass);  // a pinned particle (w = 0) has not moved
    if (momentum) checkMomentum(before_, p, pass);  // constraints between particles keep the momentum
}

double PbdSimulation::rmsBendingError() const {
    if (stencils_.empty()) return 0.0;
    double s = 0.0;
    for (const auto& b : stencils_) {
        const double e = bendingAngle(bendingGradients(P_.x.col(b.i1), P_.x.col(b.i2), P_.x.col(b.i3), P_.x.col(b.i4))) - b.phi0;
        s += e * e;
    }
    return std::sqrt(s / static_cast<double>(stencils_.size()));
}

double PbdSimulation::maxPenetration() const {
    const double h = scene_.solver.thickness;
    double m = 0.0;
    for (int i = 0; i < P_.size(); ++i)
        for (const Collider& c : scene_.colliders) {
            m = std::max(m, h - colliderDistance(c, P_.x.col(i)));
        }
    return m;
}

double PbdSimulation::minPairDistance() const {
    const double h = scene_.self_collision.thickness;
    double m2 = INFINITY;
    for (int i = 0; i < P_.size(); ++i)
        for (int j = i + 1; j < P_.size(); ++j)
            if ((rest_.col(i) - rest_.col(j)).squaredNorm() >= h * h) m2 = std::min(m2, (P_.x.col(i) - P_.x.col(j)).squaredNorm());
    return std::sqrt(m2);
}

void PbdSimulation::addMetrics(std::vector<Metric>& m) const {
    if (!stencils_.empty()) m.push_back({"rms_bending_error", rmsBendingError(), "rad"});
    if (!scene_.colliders.empty()) m.push_back({"max_penetration", maxPenetration(), "m"});
    if (selfPass_ >= 0) m.push_back({"min_pair_distance", minPairDistance(), "m"});
}

}  // namespace clothlab
