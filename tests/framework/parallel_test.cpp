// Two cores (solver.threads): the colour groups the PBD sweeps run in parallel share no particle
// (checked by brute force), and a run on two threads gives the same state bit for bit as the serial
// run (threads = 1), for PBD and XPBD with distance, bending and collision constraints.
#include <cmath>
#include <cstring>
#include <set>

#include <gtest/gtest.h>

#include "clothlab/core/input_error.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/sim/mass_spring.h"
#include "clothlab/sim/pbd.h"

using namespace clothlab;

namespace {
Scene scene(const std::string& name, std::vector<std::string> sets) {
    return loadScene(std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/" + name + ".json", sets);
}

// Every group's constraints, by brute force: no particle appears twice in one group. Returns the
// number of violations; also checks that the groups cover the list in order.
template <class Particles>
int sharedParticles(const SweepPlan& plan, size_t count, const Particles& particlesOf) {
    EXPECT_GE(plan.groups.size(), 2u);
    EXPECT_EQ(plan.groups.front(), 0);
    EXPECT_EQ(plan.groups.back(), static_cast<int>(count));
    int shared = 0;
    for (size_t g = 0; g + 1 < plan.groups.size(); ++g) {
        EXPECT_LT(plan.groups[g], plan.groups[g + 1]) << "empty group " << g;
        std::set<int> seen;
        for (int n = plan.groups[g]; n < plan.groups[g + 1]; ++n)
            for (int i : particlesOf(n))
                if (!seen.insert(i).second) ++shared;
    }
    return shared;
}

// x and v after `steps` steps, with the given number of threads.
std::pair<Matrix3X, Matrix3X> run(const std::string& name, std::vector<std::string> sets, int threads, int steps) {
    sets.push_back("solver.threads=" + std::to_string(threads));
    auto sim = makeSimulation(scene(name, sets));
    for (int k = 0; k < steps; ++k) sim->step();
    return {sim->state().x, sim->state().v};
}

bool bitIdentical(const Matrix3X& a, const Matrix3X& b) {
    if (a.cols() != b.cols()) return false;
    return std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<size_t>(a.size())) == 0;
}
}  // namespace

TEST(Parallel, NoTwoConstraintsOfAColourGroupShareAParticle) {
    const PbdSimulation sim(scene("pbd_sphere", {"cloth.nx=24", "cloth.ny=17", "solver.threads=2"}));
    const auto& links = sim.distanceLinks();
    const auto& stencils = sim.bendingStencilList();
    EXPECT_EQ(sharedParticles(sim.distancePlan(), links.size(),
                              [&](int n) { return std::vector<int>{links[n].i, links[n].j}; }),
              0);
    EXPECT_EQ(sharedParticles(sim.bendingPlan(), stencils.size(),
                              [&](int n) {
                                  const BendingStencil& stencil = stencils[n];
                                  return std::vector<int>{stencil.i1, stencil.i2, stencil.i3, stencil.i4};
                              }),
              0);
    // Colour order makes few, large groups (a grid with diagonals needs a handful of colours).
    EXPECT_LE(sim.distancePlan().groups.size(), 16u);
    EXPECT_LE(sim.bendingPlan().groups.size(), 32u);
    EXPECT_EQ(sim.distancePlan().threads, 2);
}

TEST(Parallel, TheCheckSeesASharedParticle) {
    // The brute-force check can fail: one group holding two links of particle 1.
    SweepPlan plan{{0, 2}, 2};
    const std::vector<DistanceLink> links = {{0, 1, 1.0}, {1, 2, 1.0}};
    EXPECT_EQ(sharedParticles(plan, links.size(), [&](int n) { return std::vector<int>{links[n].i, links[n].j}; }), 1);
}

TEST(Parallel, SweepPlanSplitsAtEverySharedParticleInAnyOrder) {
    // A chain 0-1-2-3-4 in index order: every link shares a particle with the one before it.
    std::vector<Eigen::Vector4i> chain;
    for (int i = 0; i < 4; ++i) chain.emplace_back(i, i + 1, -1, -1);
    EXPECT_EQ(sweepPlan(chain, 5, 2).groups, (std::vector<int>{0, 1, 2, 3, 4}));
    // In colour order (even links, then odd links): two groups.
    const std::vector<Eigen::Vector4i> coloured = {chain[0], chain[2], chain[1], chain[3]};
    EXPECT_EQ(sweepPlan(coloured, 5, 2).groups, (std::vector<int>{0, 2, 4}));
}

TEST(Parallel, TwoThreadsGiveTheSerialStateBitForBit) {
    const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
        {"pbd_sphere", {"cloth.nx=40", "cloth.ny=40"}},                          // distance, bending, collision
        {"pbd_sphere", {"cloth.nx=40", "cloth.ny=40", "solver.method=xpbd"}},  // the XPBD sweeps
        {"pbd_ground", {}},
    };
    for (const auto& [name, sets] : cases) {
        const auto [x1, v1] = run(name, sets, 1, 60);
        const auto [x2, v2] = run(name, sets, 2, 60);
        EXPECT_TRUE(bitIdentical(x1, x2)) << name << " x, max difference " << (x1 - x2).cwiseAbs().maxCoeff();
        EXPECT_TRUE(bitIdentical(v1, v2)) << name << " v";
        const auto [x0, v0] = run(name, sets, 1, 59);  // and the comparison can fail: one step less differs
        EXPECT_FALSE(bitIdentical(x0, x1)) << name;
    }
}

TEST(Parallel, TheTestedClothHasGroupsLargeEnoughToRunInParallel) {
    // Groups below kParallelGroup run on one thread: the 40 x 40 cloth above must have larger ones,
    // or the bit-for-bit comparison would compare the serial sweep with itself.
    const PbdSimulation sim(scene("pbd_sphere", {"cloth.nx=40", "cloth.ny=40"}));
    std::vector<Eigen::Vector4i> sets;
    for (const BendingStencil& b : sim.bendingStencilList()) sets.emplace_back(b.i1, b.i2, b.i3, b.i4);
    const SweepPlan plan = sweepPlan(sets, sim.state().size(), 2);
    int large = 0;
    for (size_t g = 0; g + 1 < plan.groups.size(); ++g) large += plan.groups[g + 1] - plan.groups[g] >= kParallelGroup;
    EXPECT_GE(large, 4) << "of " << plan.groups.size() - 1 << " bending colour groups";
}

TEST(Parallel, ThreadsIsValidated) {
    EXPECT_THROW(scene("pbd_sphere", {"solver.threads=-1"}), InputError);
    EXPECT_THROW(scene("pbd_sphere", {"solver.threads=1.5"}), InputError);
    EXPECT_EQ(scene("pbd_sphere", {}).solver.threads, 0);
    EXPECT_GE(sweepThreads(0), 1);
    EXPECT_EQ(sweepThreads(3), 3);
}

// ---- Implicit Euler on large systems: conjugate gradients on the spring blocks ------------------
namespace {
// A 32 x 32 cloth (3000 unknowns: the block solver's size) hanging from its top edge, Δt = 0.01 s:
// a large step for these springs (Δt²k/m ≈ 10 for the structural ones).
Scene implicitCloth(double dt, int threads) {
    const std::string json = R"({"model": "cloth", "cloth": {"nx": 32, "ny": 32, "pins": ["top-edge"], "orientation": "horizontal"},
        "springs": {"structural": {"k": 100, "kd": 0.01}, "shear": {"k": 50}, "bending": {"k": 10}},
        "forces": {"air_damping": 0.001}, "solver": {"method": "implicit_euler"}})";
    return parseScene(json, "implicit", {"solver.dt=" + std::to_string(dt), "solver.threads=" + std::to_string(threads)});
}
Matrix3X implicitRun(double dt, double seconds, ImplicitSolve how, int threads = 1) {
    auto sim = makeSimulation(implicitCloth(dt, threads));
    dynamic_cast<MassSpringSimulation&>(*sim).implicitSolver().setSolve(how);
    for (int k = 0; k < static_cast<int>(std::lround(seconds / dt)); ++k) sim->step();
    return sim->state().x;
}
}  // namespace

TEST(ImplicitBlockCg, ItsSolverErrorIsFarBelowTheStepsOwnError) {
    // Against the exact solve (sparse Cholesky) after 0.5 s: the tolerance (relative residual 1e-3)
    // moves the cloth far less than halving Δt does, i.e. than the method's own error.
    const Matrix3X exact = implicitRun(0.01, 0.5, ImplicitSolve::Cholesky);
    const Matrix3X cg = implicitRun(0.01, 0.5, ImplicitSolve::BlockCg);
    const Matrix3X halfStep = implicitRun(0.005, 0.5, ImplicitSolve::Cholesky);
    const double solverError = (cg - exact).cwiseAbs().maxCoeff(), stepError = (halfStep - exact).cwiseAbs().maxCoeff();
    EXPECT_GT(stepError, 1e-3) << "the cloth must move";
    EXPECT_LT(solverError, 0.05 * stepError) << "solver " << solverError << " m, step " << stepError << " m";
}

TEST(ImplicitBlockCg, TwoThreadsGiveTheSerialStateBitForBit) {
    const Matrix3X one = implicitRun(0.01, 0.2, ImplicitSolve::BlockCg, 1);
    const Matrix3X two = implicitRun(0.01, 0.2, ImplicitSolve::BlockCg, 2);
    EXPECT_TRUE(bitIdentical(one, two)) << "max difference " << (one - two).cwiseAbs().maxCoeff();
}

TEST(ImplicitBlockCg, ReportsItsResidual) {
    auto sim = makeSimulation(implicitCloth(0.01, 1));
    for (int k = 0; k < 5; ++k) sim->step();
    double residual = -1.0, iterations = -1.0;
    for (const Metric& m : sim->metrics()) {
        if (m.name == "solve_residual") residual = m.value;
        if (m.name == "solve_iterations") iterations = m.value;
    }
    EXPECT_GT(residual, 0.0);
    EXPECT_LE(residual, 1e-3);
    EXPECT_GT(iterations, 0.0);
}
