// Stage 07's experiment, graded by the instructor (not in the student copy: no target leaves this file).
// Predict: the largest spacing a of a layer's square grid that still holds a particle dropped onto the
// centre of a square of four of its particles, when particles keep the distance h apart (the particle
// touches the four at distance h: (a / sqrt(2))^2 + z^2 = h^2 has a solution z >= 0 while a <= h sqrt(2)).
// Measure: min_pair_distance at the end of scenes/pbd_self_collision.json on the student's own code:
// gravity presses the layers together and nothing but |p_i - p_j| >= h keeps them apart, so h. The scene
// takes too long to rerun here: the measurement is graded against h and earns points only when the
// student's code rests a small layer dropped onto another at h (the same physics, rerun here).
#include <cmath>

#include <gtest/gtest.h>

#include "clothlab/exercise/07_self_collision.h"
#include "clothlab/io/scene_json.h"
#include "experiment_scenes.h"
#include "test_util.h"

using namespace clothlab;

namespace stage07 {
double dropLayerOnLayer(int n, double h, int steps, int iterations);  // tests/07_self_collision_test.cpp
}

TEST(Experiments, HoldingSpacingPredicted) {
    const double h = parseScene(kScene_pbd_self_collision, "scenes/pbd_self_collision.json").self_collision.thickness;
    EXPECT_GRADED(testing_util::gradePrediction("07_self_collision", "largest_holding_spacing", std::sqrt(2.0) * h, 0.01 * h,
                                              "the largest grid spacing that holds a dropped particle, m"));
}

TEST(Experiments, LayerDistanceMeasured) {
    const double h = parseScene(kScene_pbd_self_collision, "scenes/pbd_self_collision.json").self_collision.thickness;
    const double yours = stage07::dropLayerOnLayer(6, h, 100, 10);
    const testing::AssertionResult physics =
        std::abs(yours - h) <= 0.1 * h ? testing::AssertionSuccess()
                                       : testing::AssertionFailure() << "your code does not rest a layer dropped onto another at the "
                                                                        "separation distance (the stage's Task7_5 tests show where)";
    EXPECT_GRADED(testing_util::gradeMeasurement("07_self_collision", "layer_distance", h, 0.1 * h, physics,
                                               "min_pair_distance at the end of pbd_self_collision, m"));
}
