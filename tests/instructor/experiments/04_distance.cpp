// Stage 04's experiment, graded by the instructor (not in the student copy: no target leaves this file).
// Predict: the strain (|x_2 - x_0| - d) / d at rest of the one link of scenes/pbd_link.json (a particle
// hanging from a pin on a distance constraint of stiffness k = 0.8, d = 1 m) at dt = 0.01 s and 0.005 s.
// First principles: at rest v = 0; a step predicts the particle g dt^2 lower, stretching the link from
// s to s + g dt^2; the pin has w = 0, so the projections move only the particle, and n of them with k'
// (task 3.2) leave (1 - k) of the stretch; at rest that is s again: s = (1 - k)(s + g dt^2), so
// s = (1 - k) g dt^2 / k, whatever the mass and the iteration count, and the strain is s / d. (The link
// to the pinned corner beside the particle changes its length only in second order.)
// Measure: max_strain of `./lab run scenes/pbd_link.json ... --quiet` on the student's own constraint.
// Graded against the same run made here with the student's code, and only when that code passes a
// first-principles check: one projection at k = 1 closes the gap and conserves momentum, the run
// reproduces the theory (1 %) and gave a result (no warning: a pin that moved makes it none).
#include <cmath>

#include <gtest/gtest.h>

#include "clothlab/exercise/04_distance.h"
#include "experiment_scenes.h"
#include "test_util.h"

using namespace clothlab;

namespace {
constexpr double kSeconds = 1.0;  // the run's length, s (the scene's 100 steps of 0.01 s)

constexpr testing_util::ExperimentField kStrains[] = {  // the time step, s
    {"link_strain_dt_0_01", 0.01, "the strain at rest of the link of pbd_link at dt = 0.01 s, 1"},
    {"link_strain_dt_0_005", 0.005, "the strain at rest of the link of pbd_link at dt = 0.005 s, 1"},
};

double theoryStrain(double dt) {
    const Scene s = parseScene(kScene_pbd_link, "scenes/pbd_link.json");
    const double k = s.constraints.distance.stiffness, g = s.forces.gravity.norm(), d = s.cloth.height / (s.cloth.ny - 1);
    return (1 - k) * g * dt * dt / (k * d);
}

testing::AssertionResult projectionConservesMomentum() {
    const double gap = 0.1, m1 = 1.0, m2 = 3.0;  // m, kg, kg
    const Vec3 p1(0, 0, 0), p2(1.0 + gap, 0, 0);
    const DistanceCorrection c = projectDistanceConstraint(p1, p2, 1 / m1, 1 / m2, 1.0, 1.0);
    const double after = (p1 + c.dp1 - p2 - c.dp2).norm(), momentum = (m1 * c.dp1 + m2 * c.dp2).norm();
    if (c.dp1.allFinite() && c.dp2.allFinite() && std::abs(after - 1.0) < 1e-9 && momentum < 1e-9) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "your projection at k = 1 does not both close the gap and conserve momentum (the stage's "
                                          "Task4_3 tests show where)";
}

testing::AssertionResult gradeStrainMeasured(const testing_util::ExperimentField& st) {
    const double theory = theoryStrain(st.setting);
    const testing_util::SceneRun run = testing_util::runScene(
        kScene_pbd_link, "scenes/pbd_link.json",
        {"solver.dt=" + testing_util::num(st.setting), "solver.steps=" + std::to_string(std::llround(kSeconds / st.setting))});
    const double own = run.metric("max_strain");
    testing::AssertionResult physics = projectionConservesMomentum();
    if (physics && std::abs(own - theory) > 0.01 * theory)
        physics = testing::AssertionFailure() << "with your constraint the particle hanging from the pin does not come to rest where PBD "
                                                 "puts it (the stage's Task4_3 tests show where)";
    if (physics) physics = testing_util::runGaveAResult(run);
    return testing_util::gradeMeasurement("04_distance", st.field, own, 1e-3 * own, physics, st.what);
}
}  // namespace

TEST(Experiments, LinkStrainPredicted) {
    for (const testing_util::ExperimentField& st : kStrains) {
        const double theory = theoryStrain(st.setting);
        EXPECT_GRADED(testing_util::gradePrediction("04_distance", st.field, theory, 0.01 * theory, st.what));
    }
}

TEST(Experiments, LinkStrainMeasured) {
    for (const testing_util::ExperimentField& st : kStrains) EXPECT_GRADED(gradeStrainMeasured(st));
}
