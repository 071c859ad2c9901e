// Stage 05's experiment, graded by the instructor (not in the student copy: no target leaves this file).
// Predict: the bending error |phi - phi0| at rest of the one stencil of scenes/pbd_hinge.json (two
// triangles lying flat, one held by three pins, the free corner of the other at r = 1/sqrt(2) m from
// the shared edge) at bending stiffness 0.1 and 0.5, in rad. First principles: the free corner can only
// turn about the shared edge (its two links end at pins), and turning it by an angle changes phi by that
// angle: |grad_p phi| = 1 / r. At rest (v = 0) a step predicts the corner g dt^2 lower, turning the wing
// by g dt^2 cos(delta) / r ~ g dt^2 / r further; n bending projections with k' (task 3.2) leave (1 - k)
// of the error (the free corner is the only particle that moves, so each projection is a Newton step
// on one angle); at rest delta = (1 - k)(delta + g dt^2 / r), so delta = (1 - k) g dt^2 / (k r), whatever
// the mass and the iteration count.
// Measure: rms_bending_error of `./lab run scenes/pbd_hinge.json ... --quiet` on the student's own
// constraint. Graded against the same run made here with the student's code, and only when that code
// passes a first-principles check: one projection at k = 1 moves phi towards phi0 without creating
// momentum (all four particles free), the run reproduces the theory (2 %) and gave a result.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "clothlab/exercise/05_bending.h"
#include "experiment_scenes.h"
#include "test_util.h"

using namespace clothlab;

namespace {
constexpr testing_util::ExperimentField kDroops[] = {  // the bending stiffness
    {"bending_error_stiffness_0_1", 0.1, "the bending error at rest of the hinge of pbd_hinge at bending stiffness 0.1, rad"},
    {"bending_error_stiffness_0_5", 0.5, "the bending error at rest of the hinge of pbd_hinge at bending stiffness 0.5, rad"},
};

double theoryDroop(double k) {
    const Scene s = parseScene(kScene_pbd_hinge, "scenes/pbd_hinge.json");
    const double g = s.forces.gravity.norm(), dt = s.solver.dt;
    const double r = s.cloth.width * s.cloth.height / std::hypot(s.cloth.width, s.cloth.height);  // corner to diagonal of the square
    return (1 - k) * g * dt * dt / (k * r);
}

const Vec3 kP1(0, 0, 0), kP2(1, 0, 0), kP3(0, 1, 0), kP4(0, 1, 1);
// phi = acos(n1.n2), n1 = p2 x p3 / |p2 x p3|, n2 = p2 x p4 / |p2 x p4|, positions relative to p1.
double phiOf(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
    const Vec3 n1 = (p2 - p1).cross(p3 - p1).normalized(), n2 = (p2 - p1).cross(p4 - p1).normalized();
    return std::acos(std::clamp(n1.dot(n2), -1.0, 1.0));
}

testing::AssertionResult projectionMovesTowardsRest() {
    const double phi0 = M_PI / 2, before = phiOf(kP1, kP2, kP3, kP4);
    const BendingCorrection c = projectBendingConstraint(kP1, kP2, kP3, kP4, 1, 1, 1, 1, phi0, 1.0);
    const double after = phiOf(kP1 + c.dp1, kP2 + c.dp2, kP3 + c.dp3, kP4 + c.dp4);
    const double momentum = (c.dp1 + c.dp2 + c.dp3 + c.dp4).norm();
    if (std::isfinite(after) && std::abs(after - phi0) < 0.9 * std::abs(before - phi0) && momentum < 1e-9) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "one projection of your bending constraint at k = 1 does not move the angle towards its rest "
                                          "value without creating momentum (the stage's Task5_* tests show where)";
}

testing::AssertionResult gradeDroopMeasured(const testing_util::ExperimentField& d) {
    const double theory = theoryDroop(d.setting);
    const testing_util::SceneRun run =
        testing_util::runScene(kScene_pbd_hinge, "scenes/pbd_hinge.json", {"constraints.bending.stiffness=" + testing_util::num(d.setting)});
    const double own = run.metric("rms_bending_error");
    testing::AssertionResult physics = projectionMovesTowardsRest();
    if (physics && std::abs(own - theory) > 0.02 * theory)
        physics = testing::AssertionFailure() << "with your constraint the hinge does not come to rest where PBD puts it (the stage's "
                                                 "Task5_2 tests show where)";
    if (physics) physics = testing_util::runGaveAResult(run);
    return testing_util::gradeMeasurement("05_bending", d.field, own, 1e-3 * own, physics, d.what);
}
}  // namespace

TEST(Experiments, HingeDroopPredicted) {
    for (const testing_util::ExperimentField& d : kDroops) {
        const double theory = theoryDroop(d.setting);
        EXPECT_GRADED(testing_util::gradePrediction("05_bending", d.field, theory, 0.01 * theory, d.what));
    }
}

TEST(Experiments, HingeDroopMeasured) {
    for (const testing_util::ExperimentField& d : kDroops) EXPECT_GRADED(gradeDroopMeasured(d));
}
