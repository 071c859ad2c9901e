// Force-based simulation assembled from a scene (framework + reference stage 01, not graded).
#include <algorithm>

#include <gtest/gtest.h>

#include "clothlab/io/scene_json.h"
#include "clothlab/sim/mass_spring.h"
#include "clothlab/sim/run.h"

using namespace clothlab;

namespace {
Scene springScene(const std::vector<std::string>& sets = {}) {
    return loadScene(std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/spring.json", sets);
}
std::vector<std::string> passNames(const Simulation& sim) {
    std::vector<std::string> names;
    for (const auto& p : sim.timer().passes()) names.push_back(p.name);
    return names;
}
double metric(const Simulation& sim, const std::string& name) {
    for (const Metric& m : sim.metrics()) if (m.name == name) return m.value;
    return NAN;
}
}  // namespace

TEST(MassSpring, SpringSceneFollowsAnalyticSolution) {
    for (const char* method : {"symplectic_euler", "velocity_verlet", "rk4"}) {
        auto sim = makeSimulation(springScene({std::string("solver.method=") + method, "solver.dt=1e-4"}));
        const RunResult r = runSimulation(*sim, 20000, 1000);
        ASSERT_FALSE(r.unstable) << method;
        EXPECT_LT(metric(*sim, "max_error"), 2e-3) << method;
    }
}

TEST(MassSpring, StaticEquilibriumStretch) {
    // A damped particle settles where k (l - l0) = m g.
    auto sim = makeSimulation(springScene({"spring.kd=5", "solver.method=rk4"}));
    runSimulation(*sim, 20000, 20000);
    EXPECT_NEAR(-sim->state().x(1, 1), 1.0 + 9.81 / 100.0, 1e-6);
}

TEST(MassSpring, OnlyTheUsedPassesRun) {
    auto plain = makeSimulation(springScene());
    plain->step();
    EXPECT_EQ(passNames(*plain), (std::vector<std::string>{"forces: gravity", "forces: spring", "integrate: symplectic_euler"}));
    auto damped = makeSimulation(springScene({"forces.air_damping=0.1", "forces.gravity=[0,0,0]", "spring.kd=0.2"}));
    damped->step();
    EXPECT_EQ(passNames(*damped), (std::vector<std::string>{"forces: air damping", "forces: spring", "forces: spring damping", "integrate: symplectic_euler"}));
}

TEST(MassSpring, ChainHangsStill) {
    // Each link carries the weight below it: link i stretches by (n - i) m g / k.
    Scene s = loadScene(std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/chain.json",
                        {"chain.direction=[0,-1,0]", "forces.air_damping=0.5", "solver.method=rk4", "solver.dt=0.001"});
    auto sim = makeSimulation(s);
    runSimulation(*sim, 20000, 20000);
    const auto& x = sim->state().x;
    for (int i = 1; i < s.chain.particles; ++i) {
        const double expected = s.chain.l0 + (s.chain.particles - i) * s.chain.mass * 9.81 / s.chain.k;
        EXPECT_NEAR((x.col(i) - x.col(i - 1)).norm(), expected, 1e-6) << "link " << i;
    }
}

TEST(Run, BlowUpIsDetectedNotSilent) {
    auto sim = makeSimulation(springScene({"solver.method=explicit_euler", "spring.k=1e6", "solver.dt=0.01"}));
    const RunResult r = runSimulation(*sim, 100000, 1000);
    EXPECT_TRUE(r.unstable);
    EXPECT_NE(r.message.find("unstable at step"), std::string::npos);
    EXPECT_LT(r.steps, 100000);
}
