// Stage 05's experiment, graded by the instructor (not in the student copy: no target leaves this file).
// Predict: the dihedral angle phi = acos(n1.n2) (appendix A's convention) of the stencil p1 = 0,
// p2 = (1,0,0), p3 = (0,1,0), p4 = (0,1,1). Measure: the drooping flag's rms_bending_error after 0.5 s at
// bending stiffness 0.02 and 1 on the student's own constraint. The measurements are graded against the
// same runs made here with the student's code, and earn points only when that code passes a
// first-principles check: one projection at k = 1 moves phi towards phi0 and creates no momentum, and a
// stiffer constraint bends less.
#include <cmath>

#include <gtest/gtest.h>

#include "clothlab/exercise/05_bending.h"
#include "experiment_scenes.h"
#include "test_util.h"

using namespace clothlab;

namespace {
const Vec3 kP1(0, 0, 0), kP2(1, 0, 0), kP3(0, 1, 0), kP4(0, 1, 1);

// phi = acos(n1.n2), n1 = p2 x p3 / |p2 x p3|, n2 = p2 x p4 / |p2 x p4|, positions relative to p1.
double phiOf(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
    const Vec3 n1 = (p2 - p1).cross(p3 - p1).normalized(), n2 = (p2 - p1).cross(p4 - p1).normalized();
    return std::acos(std::clamp(n1.dot(n2), -1.0, 1.0));
}

double droopBendingError(const char* stiffness) {
    return testing_util::finalMetric(kScene_pbd_flag, "scenes/pbd_flag.json",
                                     {"forces.wind=[0,0,0]", "cloth.orientation=horizontal", "solver.steps=50",
                                      std::string("constraints.bending.stiffness=") + stiffness},
                                     "rms_bending_error");
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
}  // namespace

TEST(Experiments, DihedralAnglePredicted) {
    EXPECT_GRADED(testing_util::gradePrediction("05_bending", "dihedral_angle", phiOf(kP1, kP2, kP3, kP4), 1e-3,
                                              "phi of the stencil p1 = 0, p2 = (1,0,0), p3 = (0,1,0), p4 = (0,1,1), rad"));
}

TEST(Experiments, BendingErrorMeasured) {
    const double soft = droopBendingError("0.02"), stiff = droopBendingError("1.0");
    testing::AssertionResult physics = projectionMovesTowardsRest();
    if (physics && !(stiff < soft)) physics = testing::AssertionFailure() << "with your constraint stiffness 1 does not bend less than 0.02";
    EXPECT_GRADED(testing_util::gradeMeasurement("05_bending", "rms_bending_error_stiffness_0_02", soft, 0.05 * soft, physics,
                                               "rms_bending_error of the drooping flag after 0.5 s at bending stiffness 0.02, rad"));
    EXPECT_GRADED(testing_util::gradeMeasurement("05_bending", "rms_bending_error_stiffness_1", stiff, 0.05 * stiff, physics,
                                               "rms_bending_error of the drooping flag after 0.5 s at bending stiffness 1, rad"));
}
