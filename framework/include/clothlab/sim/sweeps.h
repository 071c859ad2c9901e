/// @file sweeps.h
/// @brief One Gauss–Seidel sweep over all constraints of one type: line (10) of the PBD loop,
/// projectConstraints(C_1, ..., C_M, p_1, ..., p_N), split by constraint type.
///
/// Each sweep visits its constraints in the given order and moves p in place right after each
/// projection (Gauss–Seidel). The projections are the stage functions (the student's or the
/// reference code): exercise 4.3 (distance), 5.2 (bending), 6.3 (collision), 7.5 and 7.6
/// (self-collision), or their XPBD forms in xpbd.h.
///
/// Two cores: the solver orders its constraints by colour (colourOrder()), so that the constraints
/// of one colour group share no particle. Projecting them in any order, or at the same time, gives
/// the same positions bit for bit; each sweep runs one group after the other and the constraints of
/// a group in parallel, each thread one contiguous share (forEachGroupShare(), the threads of
/// sim/team.h, see docs/performance.md). With SweepPlan::threads = 1 it is the plain serial loop.
#pragma once
#include <functional>
#include <vector>

#include "clothlab/exercise/05_bending.h"
#include "clothlab/exercise/06_collision.h"
#include "clothlab/exercise/07_self_collision.h"

namespace clothlab {

/// Colour groups with fewer constraints than this are swept by one thread even when SweepPlan::threads
/// is larger: below it, starting the threads and waiting at the group's end cost more than they save
/// (the same result either way).
constexpr int kParallelGroup = 256;

/// A distance constraint between particles i and j with rest length d (an edge of the cloth).
struct DistanceLink {
    int i = 0;        ///< first particle
    int j = 0;        ///< second particle
    double d = 0.0;   ///< rest length, m
};

/// How a sweep runs: the colour groups of its constraint list and the number of threads.
struct SweepPlan {
    /// Group g holds the constraints groups[g] .. groups[g+1] − 1 (groups[0] = 0, the last entry is
    /// the number of constraints); no two constraints of one group share a particle. Empty (the
    /// default): the whole list is one group, swept serially in its order.
    std::vector<int> groups;
    int threads = 1;  ///< threads that sweep one group (1: serial, the exact teaching run)
};

/// The groups of a constraint list: maximal runs of consecutive constraints of which no two share a
/// particle (a constraint that shares a particle with the current group starts the next one). For a
/// list in colourOrder() these are exactly its colour groups: first-fit gave a constraint colour
/// c + 1 only because it shares a particle with one of colour c.
/// @param particles   the particles of each constraint in sweep order (−1: unused slot)
/// @param nParticles  number of particles N (indices are below it)
/// @param threads     threads per group, ≥ 1
/// @return            the plan
SweepPlan sweepPlan(const std::vector<Eigen::Vector4i>& particles, int nParticles, int threads);

/// The most threads for `solver.threads`: the value itself if ≥ 1, else (0) defaultThreads() (all
/// cores, or OMP_NUM_THREADS; with 0 the solver's AdaptiveTeam uses 1 or this many, whichever is faster).
/// @param requested  solver.threads, ≥ 0
/// @return           ≥ 1
int sweepThreads(int requested);

/// The colour-group loop every sweep shares (the solver's sweeps and registered kernels): group after
/// group, sweep(begin, end) over the items groups[g] .. groups[g+1] − 1 of group g. With
/// n = teamThreads(threads) ≥ 2 (threads, capped by the solver's AdaptiveTeam) and at least minParallel
/// items in the group, thread t of n sweeps the share [first + ⌊size·t/n⌋, first + ⌊size·(t+1)/n⌋) of
/// it at the same time (runShares(); the items of a group must be independent); otherwise one call
/// sweeps the whole group.
/// An exception thrown by sweep leaves after its group (the first one, if several threads throw).
/// @param groups       group boundaries: groups[0] = 0, the last entry the number of items (SweepPlan::groups)
/// @param threads      the most threads, ≥ 1
/// @param minParallel  the smallest group, in items, that is split over the threads
/// @param sweep        sweeps the items [begin, end) in order
void forEachGroupShare(const std::vector<int>& groups, int threads, int minParallel,
                       const std::function<void(int begin, int end)>& sweep);

/// PBD distance sweep: for every link, \f$ \vec p_i \mathrel{+}= \Delta\vec p_1,\ \vec p_j \mathrel{+}= \Delta\vec p_2 \f$
/// with the corrections of projectDistanceConstraint() (exercise 4.3).
/// @param links  the constraints, in the order they are projected
/// @param w      inverse masses, length N, 1/kg
/// @param k      per-iteration stiffness k' in [0, 1]
/// @param p      predicted positions, 3 x N, m (updated in place)
/// @param plan   colour groups of links and threads (default: serial, in the given order)
void projectDistanceSweep(const std::vector<DistanceLink>& links, const VectorX& w, double k, Matrix3X& p,
                          const SweepPlan& plan = {});

/// PBD bending sweep: for every stencil, \f$ \vec p_{i_m} \mathrel{+}= \Delta\vec p_m \f$ (m = 1..4) with the
/// corrections of projectBendingConstraint() (exercise 5.2).
/// @param stencils  the constraints with their rest angles φ0, in the order they are projected
/// @param w         inverse masses, length N, 1/kg
/// @param k         per-iteration stiffness k' in [0, 1]
/// @param p         predicted positions, 3 x N, m (updated in place)
/// @param plan      colour groups of stencils and threads
void projectBendingSweep(const std::vector<BendingStencil>& stencils, const VectorX& w, double k, Matrix3X& p,
                         const SweepPlan& plan = {});

/// XPBD distance sweep: projectDistanceXpbd() for every link, \f$ \tilde\alpha = \alpha/\Delta t^2 \f$.
/// @param links       the constraints, in the order they are projected
/// @param w           inverse masses, length N, 1/kg
/// @param alphaTilde  compliance over the squared (sub)step, α/Δt², kg⁻¹
/// @param lambda      one multiplier λ per link (kg m), updated; zero at the start of every (sub)step
/// @param p           predicted positions, 3 x N, m (updated in place)
/// @param plan        colour groups of links and threads
void projectDistanceSweepXpbd(const std::vector<DistanceLink>& links, const VectorX& w, double alphaTilde,
                              std::vector<double>& lambda, Matrix3X& p, const SweepPlan& plan = {});

/// XPBD bending sweep: projectBendingXpbd() for every stencil, \f$ \tilde\alpha = \alpha/\Delta t^2 \f$.
/// @param stencils    the constraints, in the order they are projected
/// @param w           inverse masses, length N, 1/kg
/// @param alphaTilde  compliance of the angle over the squared (sub)step, α/Δt²
/// @param lambda      one multiplier λ per stencil, updated; zero at the start of every (sub)step
/// @param p           predicted positions, 3 x N, m (updated in place)
/// @param plan        colour groups of stencils and threads
void projectBendingSweepXpbd(const std::vector<BendingStencil>& stencils, const VectorX& w, double alphaTilde,
                             std::vector<double>& lambda, Matrix3X& p, const SweepPlan& plan = {});

/// Collision sweep: \f$ \vec p_i \mathrel{+}= \f$ projectCollisionConstraint() (exercise 6.3) for every
/// collision constraint of this step. The contacts of one particle are projected one after the
/// other in their order; different particles in parallel, when the contacts of each particle are
/// consecutive and the particles increase along the list (the order line (8) makes them in),
/// else serially.
/// @param contacts  the collision constraints made by line (8) in this step
/// @param w         inverse masses, length N, 1/kg
/// @param h         collision thickness h, m
/// @param p         predicted positions, 3 x N, m (updated in place)
/// @param threads   threads, ≥ 1 (1: serial)
void projectCollisionSweep(const std::vector<CollisionConstraint>& contacts, const VectorX& w, double h, Matrix3X& p,
                           int threads = 1);

/// Self-collision sweep: for every pair (i, j) of findNeighbourPairs() (exercise 7.4), read as the
/// inequality |p_i − p_j| ≥ h: the separation of projectSeparation() (exercise 7.5) to the distance h,
/// then, with μ > 0, the friction between the layers of layerFriction() (exercise 7.6) with the depth
/// δ = h − |p_i − p_j| the separation removed.
/// @param pairs  the pairs found at line (8) in this step (pairs closer than h at rest left out)
/// @param h      self-collision thickness h, m: the separation distance of every pair
/// @param x      positions at the start of the step, 3 x N, m
/// @param w      inverse masses, length N, 1/kg
/// @param mu     friction coefficient μ ≥ 0 between the layers
/// @param p      predicted positions, 3 x N, m (updated in place)
void projectSelfCollisionSweep(const std::vector<ParticlePair>& pairs, double h, const Matrix3X& x, const VectorX& w,
                               double mu, Matrix3X& p);

}  // namespace clothlab
