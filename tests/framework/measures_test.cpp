// One meaning per quantity: the report's measures are defined once and mean the same for every
// method; the pass timer nests; a failed step is reported, never turned into NaN. (Not graded.)
#include <chrono>
#include <cmath>
#include <thread>

#include <gtest/gtest.h>

#include "clothlab/core/input_error.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/sim/mass_spring.h"
#include "clothlab/sim/run.h"

using namespace clothlab;

namespace {
Scene sceneFile(const std::string& name, const std::vector<std::string>& sets = {}) {
    return loadScene(std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/" + name + ".json", sets);
}
const Metric* find(const std::vector<Metric>& ms, const std::string& name) {
    for (const Metric& m : ms)
        if (m.name == name) return &m;
    return nullptr;
}
}  // namespace

// The same cloth, once as a mass-spring network and once as PBD, put into the same stretched
// shape: every stretch measure must agree, as a fraction with unit "1". A uniform stretch by
// 10 % in both directions stretches every edge by exactly 0.1 (an independent expectation).
TEST(Measures, StrainIsTheSameFractionForEveryMethod) {
    for (const std::string m : {"symplectic_euler", "implicit_euler", "pbd", "xpbd"}) {
        auto sim = makeSimulation(sceneFile("mfn_hanging", {"solver.method=" + m, "constraints.distance.stiffness=1"}));
        State& s = sim->state();
        const Vec3 anchor = s.x.col(0);
        for (int i = 0; i < s.size(); ++i) s.x.col(i) = anchor + 1.1 * (s.x.col(i) - anchor);
        const std::vector<Metric> ms = sim->metrics();
        const Metric* max = find(ms, "max_strain");
        const Metric* rms = find(ms, "rms_strain");
        ASSERT_TRUE(max && rms) << m << ": every cloth reports max_strain and rms_strain";
        EXPECT_EQ(max->unit, "1") << m;
        EXPECT_EQ(rms->unit, "1") << m;
        EXPECT_NEAR(max->value, 0.1, 1e-12) << m << ": a 10 % stretch is 0.1, not 10";
        EXPECT_NEAR(rms->value, 0.1, 1e-12) << m;
    }
}

// Report units: every metric of every shipped kind of scene has a unit, strain is never in percent.
TEST(Measures, EveryMetricHasAUnitAndNoneIsPercent) {
    for (const std::string name : {"spring", "chain", "mfn_hanging", "pbd_sphere"}) {
        auto sim = makeSimulation(sceneFile(name));
        sim->step();
        for (const Metric& m : sim->metrics()) {
            EXPECT_FALSE(m.unit.empty()) << name << ": " << m.name;
            EXPECT_NE(m.unit, "%") << name << ": " << m.name;
        }
    }
}

// The energy is defined once: kinetic + gravity (+ springs), and PBD reports it with its drift too.
TEST(Measures, EnergyAndDriftForEveryMethod) {
    for (const std::string m : {"symplectic_euler", "pbd"}) {
        auto sim = makeSimulation(sceneFile("mfn_hanging", {"solver.method=" + m}));
        const std::vector<Metric> ms = sim->metrics();
        ASSERT_TRUE(find(ms, "energy") && find(ms, "energy_drift")) << m;
        EXPECT_EQ(find(ms, "energy_drift")->value, 0.0) << m << ": no drift before the first step";
        EXPECT_EQ(find(ms, "energy")->value, sim->energy()) << m;
    }
}

// max_error is the largest error after ANY step, not only after the steps that made a report row.
TEST(Measures, MaxErrorIsOverEveryStepNotOnlyTheReportRows) {
    const Scene sc = sceneFile("spring", {"solver.method=explicit_euler", "solver.dt=0.01"});
    auto sparse = makeSimulation(sc);
    const RunResult r = runSimulation(*sparse, 300, 300);  // two rows: step 0 and step 300
    auto dense = makeSimulation(sc);
    double largest = 0.0;
    for (int k = 0; k < 300; ++k) {
        dense->step();
        largest = std::max(largest, dynamic_cast<MassSpringSimulation&>(*dense).analyticError());
    }
    ASSERT_EQ(r.rows.size(), 2u);
    const Metric* max = find(r.rows.back().metrics, "max_error");
    ASSERT_NE(max, nullptr);
    EXPECT_EQ(max->value, largest);
    EXPECT_GT(max->value, find(r.rows.back().metrics, "error")->value) << "the test needs a run whose error is not largest at the end";
}

// The old name with two meanings is an input error that names both new fields.
TEST(Measures, OldDampingFieldIsAClearError) {
    try {
        sceneFile("pbd_hanging", {"forces.damping=0.1"});
        FAIL() << "forces.damping must be rejected";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("forces.damping"), std::string::npos) << what;
        EXPECT_NE(what.find("forces.air_damping"), std::string::npos) << what;
        EXPECT_NE(what.find("pbd.damping"), std::string::npos) << what;
    }
    EXPECT_THROW(sceneFile("pbd_hanging", {"pbd.damping=1.5"}), InputError) << "k_damping is in [0, 1]";
    EXPECT_NO_THROW(sceneFile("mfn_hanging", {"forces.air_damping=3"})) << "air damping is a force coefficient, N s/m";
}

// Air damping is a force, -c v, with the same meaning for PBD as for the force-based methods: a
// free particle cloud with no gravity loses momentum at the rate c/m (dv/dt = -c v / m).
TEST(Measures, AirDampingMeansTheSameForceForEveryMethod) {
    for (const std::string m : {"symplectic_euler", "pbd"}) {
        auto sim = makeSimulation(sceneFile("mfn_hanging", {"solver.method=" + m, "forces.gravity=[0,0,0]", "forces.air_damping=0.01",
                                                           "cloth.pins=[]", "springs.structural.kd=0", "springs.shear.kd=0"}));
        State& s = sim->state();
        s.v.colwise() = Vec3(1, 0, 0);
        const double mi = 1.0 / s.w[0];
        const double dt = sim->scene().solver.dt;
        const int steps = 100;
        for (int k = 0; k < steps; ++k) sim->step();
        const double expected = std::pow(1.0 - dt * 0.01 / mi, steps);  // forward step of dv/dt = -(c/m) v
        EXPECT_NEAR(s.v.row(0).mean(), expected, 2e-3) << m;
    }
}

// Scoped timers nest: an inner pass's time is booked on it and not on the outer pass.
TEST(PassTimer, NestedScopesBookSelfTime) {
    PassTimer timer;
    const int outer = timer.add("outer"), inner = timer.add("inner");
    const auto t0 = std::chrono::steady_clock::now();
    {
        auto a = timer.time(outer);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        {
            auto b = timer.time(inner);
            std::this_thread::sleep_for(std::chrono::milliseconds(30));
        }
    }
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto& p = timer.passes();
    EXPECT_EQ(p[0].calls, 1);
    EXPECT_EQ(p[1].calls, 1);
    EXPECT_GE(p[1].seconds, 0.030);
    EXPECT_GE(p[0].seconds, 0.020);
    EXPECT_LT(p[0].seconds, total - p[1].seconds + 1e-9) << "the inner 30 ms must not be booked on the outer pass";
    EXPECT_LE(p[0].seconds + p[1].seconds, total) << "the passes add up to at most the wall time";
    EXPECT_GE(p[0].seconds + p[1].seconds, 0.050) << "the passes add up to at least the 50 ms slept in them";
}

// A step the method cannot take is reported as unstable with its reason, never as NaN.
TEST(Run, SolverFailureIsReportedWithTheOneMessage) {
    struct Failing : MassSpringSimulation {
        using MassSpringSimulation::MassSpringSimulation;
        int calls = 0;
        void step() override {
            if (++calls == 3) throw SolverFailure("implicit Euler: test failure");
            MassSpringSimulation::step();
        }
    };
    const Scene sc = sceneFile("spring");
    Failing sim(sc, makeSingleSpring(sc.spring));
    const RunResult r = runSimulation(sim, 10, 1);
    EXPECT_TRUE(r.unstable);
    EXPECT_EQ(r.steps, 3);
    EXPECT_EQ(r.message.rfind("unstable at step 3 (t = ", 0), 0u) << r.message;
    EXPECT_NE(r.message.find("implicit Euler: test failure"), std::string::npos) << r.message;
    EXPECT_TRUE(sim.state().isFinite()) << "a failed step leaves the state as it was";
}

TEST(Run, InstabilityReasonNamesWhatWentWrong) {
    State s;
    s.resize(2);
    EXPECT_EQ(instabilityReason(s, 10.0), "");
    s.x(0, 1) = 11.0;
    EXPECT_NE(instabilityReason(s, 10.0).find("left the region |x| < 10 m"), std::string::npos);
    s.x(0, 1) = NAN;
    EXPECT_EQ(instabilityReason(s, 10.0), "position is NaN or infinite");
    s.x(0, 1) = 0.0;
    s.v(2, 0) = INFINITY;
    EXPECT_EQ(instabilityReason(s, 10.0), "velocity is NaN or infinite");
}
