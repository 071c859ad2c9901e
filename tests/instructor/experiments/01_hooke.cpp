// Stage 01's experiment, graded by the instructor (not in the student copy: no target leaves this file).
// Predict: the energy drift E(1 s) - E(0) of the particle of scenes/spring.json stepped with explicit
// Euler at dt = 1 ms and at dt = 0.5 ms, in J. First principles: the particle hangs from the anchor and
// moves along the vertical; about its equilibrium length l0 + m g / k it is an undamped linear oscillator
// (the spring's and gravity's energies add up to k u^2 / 2 plus a constant, u the displacement from
// equilibrium), so E - E(0) is the change of m v^2 / 2 + k u^2 / 2. One explicit Euler step maps
// (u, v) to (u + dt v, v - dt omega^2 u), which multiplies v^2 + omega^2 u^2 by (1 + omega^2 dt^2)
// exactly; after N = T / dt steps from rest at amplitude A: drift = k A^2 / 2 ((1 + omega^2 dt^2)^N - 1).
// Measure: energy_drift of `./lab run scenes/spring.json --set solver.method=explicit_euler ... --seconds 1` on the
// student's own code. Graded against the same run made here with the student's code, and only when that
// run reproduces the theory (1e-3) and gave a result (no warning).
#include <cmath>

#include <gtest/gtest.h>

#include "clothlab/exercise/01_hooke.h"
#include "experiment_scenes.h"
#include "test_util.h"

using namespace clothlab;

namespace {
constexpr double kSeconds = 1.0;  // the run's length, s (before the drift reaches the run's energy-growth warning)

constexpr testing_util::ExperimentField kDrifts[] = {  // the time step, s
    {"energy_drift_dt_1ms", 0.001, "the energy drift E(1 s) - E(0) of the spring with explicit Euler at dt = 1 ms, J"},
    {"energy_drift_dt_0_5ms", 0.0005, "the energy drift E(1 s) - E(0) of the spring with explicit Euler at dt = 0.5 ms, J"},
};

long long stepsOf(double dt) { return std::llround(kSeconds / dt); }

// The drift from first principles (header comment), for the scene as shipped.
testing::AssertionResult theoryDrift(double dt, double* drift) {
    const Scene s = parseScene(kScene_spring, "scenes/spring.json");
    const SingleSpringSpec& sp = s.spring;
    const Vec3 r = sp.start - sp.anchor, g = s.forces.gravity;
    if (sp.kd != 0 || sp.velocity.norm() != 0 || r.cross(g).norm() > 1e-12 * r.norm() * g.norm() || r.dot(g) <= 0)
        return testing::AssertionFailure() << "scenes/spring.json no longer starts at rest below the anchor without damping: this "
                                              "test's theory does not apply (tests/instructor/experiments/01_hooke.cpp)";
    const double omega2 = sp.k / sp.mass, amplitude = r.norm() - (sp.l0 + sp.mass * g.norm() / sp.k);
    *drift = 0.5 * sp.k * amplitude * amplitude * (std::pow(1 + omega2 * dt * dt, static_cast<double>(stepsOf(dt))) - 1);
    return testing::AssertionSuccess();
}

testing::AssertionResult gradeDriftMeasured(const testing_util::ExperimentField& d) {
    double theory = 0;
    testing::AssertionResult physics = theoryDrift(d.setting, &theory);
    const testing_util::SceneRun run =
        testing_util::runScene(kScene_spring, "scenes/spring.json",
                               {"solver.method=explicit_euler", "solver.dt=" + testing_util::num(d.setting), "solver.steps=" + std::to_string(stepsOf(d.setting))});
    const double own = run.metric("energy_drift");
    if (physics && std::abs(own - theory) > 1e-3 * std::abs(theory))
        physics = testing::AssertionFailure() << "your explicit Euler does not change the energy of the undamped spring as the method does "
                                                 "(the stage's Task1_1 and Task1_3 tests show where)";
    if (physics) physics = testing_util::runGaveAResult(run);
    return testing_util::gradeMeasurement("01_hooke", d.field, own, 1e-3 * std::abs(own), physics, d.what);
}
}  // namespace

TEST(Experiments, EnergyDriftPredicted) {
    for (const testing_util::ExperimentField& d : kDrifts) {
        double theory = 0;
        const testing::AssertionResult scene = theoryDrift(d.setting, &theory);
        EXPECT_GRADED(scene);
        if (scene) EXPECT_GRADED(testing_util::gradePrediction("01_hooke", d.field, theory, 0.01 * std::abs(theory), d.what));
    }
}

TEST(Experiments, EnergyDriftMeasured) {
    for (const testing_util::ExperimentField& d : kDrifts) EXPECT_GRADED(gradeDriftMeasured(d));
}
