// Stage 07's experiment, graded by the instructor (not in the student copy: no target leaves this file).
// Predict: the height above the pinned layer at which the small layer of scenes/pbd_layers.json comes to
// rest, in m. First principles: each particle of the upper layer lies above the centre of a square of
// side a of the lower layer, and at rest it touches the square's four corners at the distance h that
// self-collision keeps (gravity presses it down, only |p_i - p_j| >= h holds it up): its horizontal
// distance to each corner is a / sqrt(2), so (a / sqrt(2))^2 + z^2 = h^2 and z = sqrt(h^2 - a^2 / 2)
// (real while a <= h sqrt(2): above that the particle passes between the four).
// Measure: the y of particle 0 (in the upper layer) at the end of `./lab run scenes/pbd_layers.json` on
// the student's own code (the lower layer lies at y = 0). Graded against the same run made here with the
// student's code, and only when that code rests a layer dropped onto another at h (the graded test's
// drop, rerun here), the run reproduces the theory (2 %) and gave a result (no warning).
#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <gtest/gtest.h>

#include "clothlab/core/mesh.h"
#include "clothlab/exercise/07_self_collision.h"
#include "clothlab/io/scene_json.h"
#include "experiment_scenes.h"
#include "test_util.h"

using namespace clothlab;

namespace stage07 {
double dropLayerOnLayer(int n, double h, int steps, int iterations);  // tests/07_self_collision_test.cpp
}

namespace {
// The scene file as the student has it: scenes/pbd_layers.json and its mesh, written into a temporary
// folder (a graded test cannot see scenes/). Returns the scene's path there.
std::string sceneWithItsMesh() {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("clothlab_layers_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir / "meshes");
    std::ofstream(dir / "meshes" / "two_layers.obj") << kMesh_two_layers;
    return (dir / "pbd_layers.json").string();
}

// z = sqrt(h^2 - a^2 / 2): h the scene's self_collision.thickness, a the lower layer's spacing.
double theoryHeight(const Scene& s) {
    const Matrix3X& x = s.cloth.meshData->vertices;
    double a = INFINITY;  // the spacing: the shortest edge of a pinned (lower-layer) triangle
    for (const auto& t : s.cloth.meshData->triangles)
        for (int e = 0; e < 3; ++e)
            if (x(1, t[e]) == 0 && x(1, t[(e + 1) % 3]) == 0) a = std::min(a, (x.col(t[e]) - x.col(t[(e + 1) % 3])).norm());
    const double h = s.self_collision.thickness;
    return std::sqrt(h * h - a * a / 2);
}
}  // namespace

TEST(Experiments, RestHeightPredicted) {
    const std::string file = sceneWithItsMesh();
    const Scene s = parseScene(kScene_pbd_layers, file);
    const double theory = theoryHeight(s);
    EXPECT_GRADED(testing_util::gradePrediction("07_self_collision", "rest_height", theory, 0.01 * theory,
                                                "the height above the pinned layer at which the small layer comes to rest, m"));
}

TEST(Experiments, RestHeightMeasured) {
    const std::string file = sceneWithItsMesh();
    const Scene s = parseScene(kScene_pbd_layers, file);
    const double theory = theoryHeight(s), h = s.self_collision.thickness;
    testing_util::SceneRun run = testing_util::runScene(kScene_pbd_layers, file, {});
    run.command = "./lab run scenes/pbd_layers.json";
    const double own = run.sim->state().x(1, 0);
    const double dropped = stage07::dropLayerOnLayer(6, h, 100, 10);
    testing::AssertionResult physics = std::abs(dropped - h) <= 0.1 * h && std::abs(own - theory) <= 0.02 * theory
                                           ? testing::AssertionSuccess()
                                           : testing::AssertionFailure() << "your code does not rest a layer dropped onto another at the "
                                                                            "separation distance (the stage's Task7_5 tests show where)";
    if (physics) physics = testing_util::runGaveAResult(run);
    EXPECT_GRADED(testing_util::gradeMeasurement("07_self_collision", "rest_height", own, 1e-3 * theory, physics,
                                                 "the y of particle 0 at the end of pbd_layers, m"));
}
