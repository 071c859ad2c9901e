/// @file pbd.h
/// @brief Position Based Dynamics (Müller et al. 2007) and XPBD (Macklin et al. 2016) on a cloth.
///
/// Where each line of the algorithm on the slides lives:
///
/// | line | algorithm | file: function |
/// |---|---|---|
/// | (1)–(3) | forall vertices: initialise x_i, v_i, w_i = 1/m_i | sim/pbd.cpp: PbdSimulation::PbdSimulation(), with core/grid.h: makeClothGeometry() (a grid or a mesh) |
/// | (4) | loop | sim/run.cpp: runSimulation() (or the app), calling sim/pbd.cpp: PbdSimulation::step() once per frame |
/// | (5) | v_i ← v_i + Δt w_i f_ext(x_i) | exercises/03_pbd_loop/pbd_loop.cpp: pbdStep() (exercise 3.3), f_ext from sim/pbd.cpp: PbdSimulation::addExternalForces() |
/// | (6) | dampVelocities(v_1, ..., v_N) | exercises/03_pbd_loop/pbd_loop.cpp: dampVelocities() (exercise 3.1) |
/// | (7) | p_i ← x_i + Δt v_i | exercises/03_pbd_loop/pbd_loop.cpp: pbdStep() |
/// | (8) | generateCollisionConstraints(x_i → p_i) | sim/pbd.cpp: PbdSimulation::generateCollisions(), calling exercises/06_collision/collision.cpp (exercises 6.1, 6.2: planes, spheres) and sim/colliders.h: generateSolidConstraint() (boxes, capsules, meshes); with self-collision PbdSimulation::findSelfCollisions(), calling exercises/07_self_collision/self_collision.cpp (exercises 7.1–7.4) |
/// | (9)–(11) | loop solverIterations times: projectConstraints(C_1, ..., C_M+Mcoll, p_1, ..., p_N) | pbdStep() calling sim/pbd.cpp: PbdSimulation::projectConstraints(), which runs the sweeps of sim/sweeps.cpp over exercises 4.3, 5.2, 6.3, 7.5–7.6 (stiffness per iteration: exercise 3.2) |
/// | (12)–(15) | v_i ← (p_i − x_i)/Δt, x_i ← p_i | exercises/03_pbd_loop/pbd_loop.cpp: pbdStep() |
/// | (16) | velocityUpdate(v_1, ..., v_N) | exercises/06_collision/collision.cpp: velocityUpdate() (exercise 6.4) |
/// | (17) | end loop | sim/pbd.cpp: the end of PbdSimulation::step() |
///
/// Only what the scene enables becomes a callback and a timed pass: a scene without colliders never
/// calls the collision code, one without constraints.bending never calls the bending code, one without
/// self_collision never calls stage 07.
/// XPBD is the same loop with the sweeps of xpbd.h (a multiplier λ per constraint, reset every substep).
#pragma once
#include <vector>

#include "clothlab/exercise/03_pbd_loop.h"
#include "clothlab/exercise/05_bending.h"
#include "clothlab/exercise/06_collision.h"
#include "clothlab/exercise/07_self_collision.h"
#include "clothlab/sim/kernel_registry.h"
#include "clothlab/sim/simulation.h"
#include "clothlab/sim/sweeps.h"
#include "clothlab/sim/team.h"

namespace clothlab {

/// PBD or XPBD (solver.method "pbd" or "xpbd") on a cloth scene.
class PbdSimulation : public Simulation {
public:
    /// @param scene  a scene with model "cloth" and solver.method "pbd" or "xpbd"
    /// @throws InputError for a cloth mesh that cannot be read (cloth.mesh)
    explicit PbdSimulation(const Scene& scene);
    /// One frame: solver.substeps times pbdStep() (lines (5)–(16)) with Δt / substeps.
    void step() override;
    const State& state() const override { return P_; }
    State& state() override { return P_; }

    /// RMS of the bending-angle error φ − φ0 over the bending stencils, rad (0 without them).
    double rmsBendingError() const;
    /// Deepest violation of a collision constraint over particles and colliders, max(0, h − dist), m.
    double maxPenetration() const;
    /// The closest distance between two particles that are at least h apart at rest (h =
    /// self_collision.thickness), m: \f$ \min_{|X_i - X_j| \ge h} |x_i - x_j| \f$, exact, independent
    /// of stage 07 (sort and sweep along the axis of the largest extent: a pair further apart than the
    /// closest found so far along that axis is not compared). Pairs with a NaN coordinate are left out.
    double minPairDistance() const;
    /// The distance constraints (empty unless constraints.distance is enabled), in projection order.
    const std::vector<DistanceLink>& distanceLinks() const { return links_; }
    /// The bending stencils (empty unless constraints.bending is enabled), in projection order.
    const std::vector<BendingStencil>& bendingStencilList() const { return stencils_; }
    /// The colour groups of distanceLinks() and the threads that sweep them.
    const SweepPlan& distancePlan() const { return linkPlan_; }
    /// The colour groups of bendingStencilList() and the threads that sweep them.
    const SweepPlan& bendingPlan() const { return stencilPlan_; }
    /// How many threads the sweeps use: solver.threads, or for 0 the faster of 1 and all cores, timed
    /// per step().
    const AdaptiveTeam& team() const { return team_; }

protected:
    /// rms_bending_error (with bending constraints), max_penetration (with colliders) and
    /// min_pair_distance (with self-collision).
    void addMetrics(std::vector<Metric>& m) const override;

private:
    /// Line (5)'s f_ext: gravity, air damping and wind, each a timed pass.
    void addExternalForces(const Matrix3X& x, const Matrix3X& v, Matrix3X& f);
    /// Line (8): the collision constraints of x → p against every collider.
    void generateCollisions(const Matrix3X& x, const Matrix3X& p);
    /// Line (8) with self-collision: the spatial hash of p and the pairs within 1.25 h, each with the
    /// separation distance h; pairs closer than h at rest are left out (stage 07).
    void findSelfCollisions(const Matrix3X& p);
    /// Line (10): one sweep over every constraint type the scene uses.
    void projectConstraints(Matrix3X& p);
    /// One timed pass of projectConstraints(): project(p), then the invariants (checkPins; for
    /// constraints between particles, `internal`, checkMomentum on the first iteration of a step).
    template <class Project>
    void constraintPass(int pass, bool internal, Matrix3X& p, Project project);

    PbdParticles P_;                         ///< the particles: x, v, w, t and the predictions p
    PbdCallbacks callbacks_;                 ///< what pbdStep() calls, built once from the scene
    bool xpbd_ = false;                      ///< XPBD instead of PBD
    double subDt_ = 0.0;                     ///< Δt / substeps, s
    int threads_ = 1;                        ///< the most threads per colour group (solver.threads, 0 resolved)
    AdaptiveTeam team_;                      ///< the threads of each iteration: fixed, or the faster (sim/team.h)
    SweepPlan linkPlan_, stencilPlan_;       ///< colour groups of links_ and stencils_
    std::vector<DistanceLink> links_;        ///< distance constraints
    std::vector<BendingStencil> stencils_;   ///< bending constraints
    ConstraintSweep distanceSweep_;          ///< PBD and XPBD distance sweeps over links_ (kernel_registry.h)
    ConstraintSweep bendingSweep_;           ///< PBD and XPBD bending sweeps over stencils_ (kernel_registry.h)
    std::vector<double> linkLambda_;         ///< XPBD multipliers of the links
    std::vector<double> bendLambda_;         ///< XPBD multipliers of the stencils
    std::vector<CollisionConstraint> contacts_;  ///< collision constraints of the current step
    std::vector<Vec3> nearest_;                  ///< closest point of particle i on solid collider k at the last step, at i·colliders + k (speeds up a mesh's search)
    double kDistance_ = 1.0, kBending_ = 1.0;    ///< per-iteration PBD stiffness k'
    Matrix3X rest_;                              ///< rest positions X (self-collision: which pairs are neighbours)
    std::vector<ParticlePair> selfPairs_;        ///< self-collision pairs of the current step (separation distance h)
    NeighbourSearch neighbourPairs_;             ///< finds them: exercises 7.3 and 7.4, or solver.kernel's (kernel_registry.h)
    bool firstIteration_ = false;                ///< the next projectConstraints() is a step's first
    Matrix3X before_;                            ///< p before a pass (checkMomentum)
    /// What the scene uses; nothing else runs or is timed (a scene names only what it needs).
    struct Uses {
        bool gravity = false, airDamping = false, wind = false;  ///< external forces
        bool distance = false, bending = false;                  ///< constraints between particles
        bool colliders = false, selfCollision = false;           ///< collisions with colliders, with itself
    } uses_;
    /// The timer's pass ids (PassTimer::add) of the passes in use.
    struct Passes {
        int step = -1;                                  ///< lines (5)-(7) and (12)-(16): damp, predict, update
        int gravity = -1, airDamping = -1, wind = -1;   ///< external forces, line (5)
        int distance = -1, bending = -1;                ///< constraint sweeps, line (10)
        int generate = -1, collision = -1, velocity = -1;  ///< colliders: line (8), line (10), line (16)
        int hash = -1, self = -1;                       ///< self-collision: pairs (line (8)), sweep (line (10))
    } pass_;
};

}  // namespace clothlab
