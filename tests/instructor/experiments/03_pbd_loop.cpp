// Stage 03's experiment, graded by the instructor (not in the student copy: no target leaves this file).
// Predict: the energy drift E(1 s) - E(0) of the curtain of scenes/pbd_curtain.json falling freely (its
// pins removed) with dt = 0.01 s and dt = 0.005 s, in J. First principles: without a constraint that
// acts (the cloth keeps its shape, so every C stays 0) and with dampVelocities keeping the rigid motion,
// lines (5), (7), (13), (14) of the loop are symplectic Euler for every particle: after n steps
// v_n = -n g dt and y_n = y_0 - g dt^2 n (n + 1) / 2, so E_n - E_0 = M (v_n^2 / 2 + g (y_n - y_0))
// = -M g^2 dt^2 n / 2 = -M g^2 dt T / 2 at T = n dt (M the cloth's mass; the exact fall keeps E).
// Measure: energy_drift of `./lab run scenes/pbd_curtain.json --set 'cloth.pins=[]' ...` on the student's
// own loop. Graded against the same run made here with the student's code, and only when that run
// reproduces the theory (1e-6 relative) and gave a result (no warning).
#include <cmath>

#include <gtest/gtest.h>

#include "clothlab/exercise/03_pbd_loop.h"
#include "experiment_scenes.h"
#include "test_util.h"

using namespace clothlab;

namespace {
constexpr double kSeconds = 1.0;  // s

constexpr testing_util::ExperimentField kDrifts[] = {  // the time step, s
    {"energy_drift_dt_0_01", 0.01, "the energy drift E(1 s) - E(0) of the freely falling curtain with dt = 0.01 s, J"},
    {"energy_drift_dt_0_005", 0.005, "the energy drift E(1 s) - E(0) of the freely falling curtain with dt = 0.005 s, J"},
};

long long stepsOf(double dt) { return std::llround(kSeconds / dt); }

double theoryDrift(double dt) {
    const Scene s = parseScene(kScene_pbd_curtain, "scenes/pbd_curtain.json");
    const double g = s.forces.gravity.norm();
    return -0.5 * s.cloth.mass * g * g * dt * (static_cast<double>(stepsOf(dt)) * dt);
}

testing::AssertionResult gradeDriftMeasured(const testing_util::ExperimentField& d) {
    const double theory = theoryDrift(d.setting);
    const testing_util::SceneRun run = testing_util::runScene(
        kScene_pbd_curtain, "scenes/pbd_curtain.json",
        {"cloth.pins=[]", "solver.dt=" + testing_util::num(d.setting), "solver.steps=" + std::to_string(stepsOf(d.setting))});
    const double own = run.metric("energy_drift");
    testing::AssertionResult physics = testing::AssertionSuccess();
    if (std::abs(own - theory) > 1e-6 * std::abs(theory))
        physics = testing::AssertionFailure() << "with your loop a cloth in free fall does not move as lines (5)-(16) make it move (the "
                                                 "stage's Task3_1 and Task3_3 tests show where)";
    if (physics) physics = testing_util::runGaveAResult(run);
    return testing_util::gradeMeasurement("03_pbd_loop", d.field, own, 1e-3 * std::abs(own), physics, d.what);
}
}  // namespace

TEST(Experiments, FreeFallEnergyDriftPredicted) {
    for (const testing_util::ExperimentField& d : kDrifts) {
        const double theory = theoryDrift(d.setting);
        EXPECT_GRADED(testing_util::gradePrediction("03_pbd_loop", d.field, theory, 0.01 * std::abs(theory), d.what));
    }
}

TEST(Experiments, FreeFallEnergyDriftMeasured) {
    for (const testing_util::ExperimentField& d : kDrifts) EXPECT_GRADED(gradeDriftMeasured(d));
}
