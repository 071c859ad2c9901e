// Stage 04's experiment, graded by the instructor (not in the student copy: no target leaves this file).
// Predict: how far one projection at k = 1 moves the 1 kg particle of a 1 kg / 3 kg pair whose distance
// constraint is 0.1 m too long (momentum is conserved: task 4.3's mass weighting). Measure: the curtain's
// max_strain after 3 s at distance stiffness 1 and 0.9 on the student's own constraint. The measurements
// are graded against the same runs made here with the student's code, and earn points only when that
// code passes a first-principles check: one projection at k = 1 closes the gap exactly and conserves
// momentum, and a softer constraint lets the curtain stretch more.
#include <cmath>

#include <gtest/gtest.h>

#include "clothlab/exercise/04_distance.h"
#include "experiment_scenes.h"
#include "test_util.h"

using namespace clothlab;

namespace {
constexpr double kGap = 0.1, kLightMass = 1.0, kHeavyMass = 3.0;  // m, kg, kg

double curtainStrain(const char* stiffness) {
    return testing_util::finalMetric(kScene_pbd_curtain, "scenes/pbd_curtain.json",
                                     {std::string("constraints.distance.stiffness=") + stiffness}, "max_strain");
}

testing::AssertionResult projectionConservesMomentum() {
    const Vec3 p1(0, 0, 0), p2(1.0 + kGap, 0, 0);
    const DistanceCorrection c = projectDistanceConstraint(p1, p2, 1 / kLightMass, 1 / kHeavyMass, 1.0, 1.0);
    const double after = (p1 + c.dp1 - p2 - c.dp2).norm(), momentum = (kLightMass * c.dp1 + kHeavyMass * c.dp2).norm();
    if (c.dp1.allFinite() && c.dp2.allFinite() && std::abs(after - 1.0) < 1e-9 && momentum < 1e-9) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "your projection at k = 1 does not both close the gap and conserve momentum (the stage's "
                                          "Task4_3 tests show where)";
}
}  // namespace

TEST(Experiments, LightParticleCorrectionPredicted) {
    const double w1 = 1 / kLightMass, w2 = 1 / kHeavyMass;
    EXPECT_GRADED(testing_util::gradePrediction("04_distance", "light_particle_correction", kGap * w1 / (w1 + w2), 1e-4,
                                              "how far one projection at k = 1 moves the 1 kg particle, m"));
}

TEST(Experiments, CurtainStrainMeasured) {
    const double stiff = curtainStrain("1.0"), soft = curtainStrain("0.9");
    testing::AssertionResult physics = projectionConservesMomentum();
    if (physics && !(soft > stiff)) physics = testing::AssertionFailure() << "with your constraint k = 0.9 does not stretch more than k = 1";
    EXPECT_GRADED(testing_util::gradeMeasurement("04_distance", "max_strain_stiffness_1", stiff, 0.03 * stiff, physics,
                                               "max_strain of pbd_curtain after 3 s at distance stiffness 1, 1"));
    EXPECT_GRADED(testing_util::gradeMeasurement("04_distance", "max_strain_stiffness_0_9", soft, 0.03 * soft, physics,
                                               "max_strain of pbd_curtain after 3 s at distance stiffness 0.9, 1"));
}
