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
    uses_.gravity = f.gravity.squaredNorm() > 0.0;
    uses_.airDamping = f.air_damping > 0.0;
    uses_.wind = f.wind.squaredNorm() > 0.0;
    uses_.distance = scene.constraints.distance.enabled;
    uses_.bending = scene.constraints.bending.enabled;
    uses_.colliders = !scene.colliders.empty();
    uses_.selfCollision = scene.self_collision.enabled;
    if (uses_.gravity) pass_.gravity = timer_.add("forces: gravity");
    if (uses_.airDamping) pass_.airDamping = timer_.add("forces: air damping");
    if (uses_.wind) pass_.wind = timer_.add("forces: wind");
    if (uses_.gravity || uses_.airDamping || uses_.wind)
        callbacks_.externalForces = [this](const Matrix3X& x, const Matrix3X& v, Matrix3X& f) { addExternalForces(x, v, f); };
    pass_.step = timer_.add(std::string(methodName(sv.method)) + ": damp, predict, update");
    if (uses_.distance) {
        pass_.distance = timer_.add("constraints: distance");
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
    if (uses_.bending) {
        pass_.bending = timer_.add("constraints: bending");
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
    if (uses_.colliders) {
        pass_.generate = timer_.add("collisions: generate");
        pass_.collision = timer_.add("constraints: collision");
        pass_.velocity = timer_.add("collisions: velocity update");
        callbacks_.velocityUpdate = [this](const Matrix3X&, Matrix3X& v) {
            auto timed = timer_.time(pass_.velocity);
            velocityUpdate(v, contacts_);  // exercise 6.4
            checkBlowUp(v, pass_.velocity);
        };
    }
    if (uses_.selfCollision) {  // stage 07: the cloth against itself
        pass_.hash = timer_.add("self-collision: hash and pairs");
        pass_.self = timer_.add("constraints: self-collision");
        rest_ = P_.x;
        neighbourPairs_ = makeNeighbourSearch(sv.kernel);  // "exercise": exercises 7.3 and 7.4
    }
    if (uses_.colliders || uses_.selfCollision)
        callbacks_.generateCollisionConstraints = [this](const Matrix3X& x, const Matrix3X& p) {
            if (uses_.colliders) generateCollisions(x, p);
            if (uses_.selfCollision) findSelfCollisions(p);
        };
    if (uses_.distance || uses_.bending || uses_.colliders || uses_.selfCollision)
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
        auto timed = timer_.time(pass_.step);  // the passes called back from pbdStep() are booked on their own
        firstIteration_ = true;
        pbdStep(P_, callbacks_, scene_.pbd.damping, sv.iterations, subDt_);  // lines (5)-(16), exercise 3.3
        checkBlowUp(P_.x, pass_.step);  // lines (12)-(16): v and x from p
    }
    P_.t += sv.dt;
}

void PbdSimulation::addExternalForces(const Matrix3X& x, const Matrix3X& v, Matrix3X& f) {
    const ForcesSpec& spec = scene_.forces;
    if (uses_.gravity) {  // m_i g
        auto timed = timer_.time(pass_.gravity);
        for (int i = 0; i < f.cols(); ++i)
            if (P_.w[i] > 0.0) f.col(i) += spec.gravity / P_.w[i];
    }
    if (uses_.airDamping) {  // −c v_i
        auto timed = timer_.time(pass_.airDamping);
        f -= spec.air_damping * v;
    }
    if (uses_.wind) {  // per triangle: drag · A · ((v_wind − v̄)·n̂) n̂, split equally over its three particles
        auto timed = timer_.time(pass_.wind);
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
    auto timed = timer_.time(pass_.generate);
    contacts_.clear();
    const double h = scene_.solver.thickness;
    const size_t nc = scene_.colliders.size();
    // the closest surface point of each particle and solid collider at the last step (NaN: none yet)
    if (nearest_.size() != nc * static_cast<size_t>(x.cols())) nearest_.assign(nc * static_cast<size_t>(x.cols()), Vec3::Constant(NAN));
    CollisionConstraint c;
    for (int i = 0; i < x.cols(); ++i) {
        if (P_.w[i] <= 0.0) continue;
        for (size_t k = 0; k < nc; ++k) {
            const Collider& col = scene_.colliders[k];
            const Vec3 xi = x.col(i), pi = p.col(i);
            const bool hit =
                col.type == Collider::Type::Plane    ? generatePlaneConstraint(i, xi, pi, planeCollider(col), h, subDt_, &c)  // exercise 6.1
                : col.type == Collider::Type::Sphere ? generateSphereConstraint(i, xi, pi, sphereCollider(col), h, subDt_, &c)  // 6.2
                                                     : generateSolidConstraint(i, xi, pi, col, h, subDt_, &c, &nearest_[i * nc + k]);  // sim/colliders.h
            if (hit) contacts_.push_back(c);
        }
    }
}

void PbdSimulation::findSelfCollisions(const Matrix3X& p) {
    auto timed = timer_.time(pass_.hash);
    const double h = scene_.self_collision.thickness;
    selfPairs_.clear();
    // Pairs within 1.25 h: a margin of h/4 for the motion during the iterations (exercises 7.3, 7.4:
    // the spatial hash of 2N buckets, then the pairs). Pairs closer than h at rest are the cloth's own
    // neighbours, left to its distance constraints.
    const double query = 1.25 * h;
    for (const ParticlePair& q : neighbourPairs_(p, query)) {
        if (P_.w[q.i] <= 0.0 && P_.w[q.j] <= 0.0) continue;
        if ((rest_.col(q.i) - rest_.col(q.j)).squaredNorm() < h * h) continue;
        selfPairs_.push_back(q);
    }
}

// Lines (9)-(11): each constraint type the scene uses, one pass each.
void PbdSimulation::projectConstraints(Matrix3X& p) {
    const VectorX& w = P_.w;
    const double dt2 = subDt_ * subDt_;
    checkPins(p, pass_.step);  // lines (5)-(7) predicted p
    checkBlowUp(p, pass_.step);
    if (uses_.distance)
        constraintPass(pass_.distance, true, p, [&](Matrix3X& q) {
            if (xpbd_) distanceSweep_.xpbd(w, scene_.constraints.distance.compliance / dt2, linkLambda_, q);
            else distanceSweep_.pbd(w, kDistance_, q);
        });
    if (uses_.bending)
        constraintPass(pass_.bending, true, p, [&](Matrix3X& q) {
            if (xpbd_) bendingSweep_.xpbd(w, scene_.constraints.bending.compliance / dt2, bendLambda_, q);
            else bendingSweep_.pbd(w, kBending_, q);
        });
    if (uses_.colliders)
        constraintPass(pass_.collision, false, p, [&](Matrix3X& q) { projectCollisionSweep(contacts_, w, scene_.solver.thickness, q, threads_); });
    if (uses_.selfCollision)
        constraintPass(pass_.self, true, p, [&](Matrix3X& q) {
            projectSelfCollisionSweep(selfPairs_, scene_.self_collision.thickness, P_.x, w, scene_.self_collision.friction, q);  // exercises 7.5, 7.6
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
    checkBlowUp(p, pass);  // (only when a blow-up is being traced to its pass)
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
    const int n = P_.size();
    Eigen::Index axis = 0;  // the axis of the largest extent
    (P_.x.rowwise().maxCoeff() - P_.x.rowwise().minCoeff()).maxCoeff(&axis);
    std::vector<double> key(static_cast<size_t>(n));  // the coordinate along it (NaN: +inf, last, never compared)
    for (int i = 0; i < n; ++i) key[i] = std::isnan(P_.x(axis, i)) ? INFINITY : P_.x(axis, i);
    std::vector<int> order(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return key[a] < key[b]; });
    double m2 = INFINITY, m = INFINITY;
    for (int a = 0; a < n; ++a)
        for (int b = a + 1, i = order[a]; b < n; ++b) {
            const int j = order[b];
            if (key[j] - key[i] >= m) break;  // every later j is further apart along the axis alone
            if ((rest_.col(i) - rest_.col(j)).squaredNorm() < h * h) continue;
            if (const double d2 = (P_.x.col(i) - P_.x.col(j)).squaredNorm(); d2 < m2) m2 = d2, m = std::sqrt(d2);
        }
    return m;
}

void PbdSimulation::addMetrics(std::vector<Metric>& m) const {
    if (!stencils_.empty()) m.push_back({"rms_bending_error", rmsBendingError(), "rad"});
    if (!scene_.colliders.empty()) m.push_back({"max_penetration", maxPenetration(), "m"});
    if (uses_.selfCollision) m.push_back({"min_pair_distance", minPairDistance(), "m"});
}

}  // namespace clothlab
