// The leave-it-out path of stage 07: linked with stage 07's untouched stubs (every function throws
// NotImplemented), every shipped scene without self_collision runs, and the one with it reaches the stub.
// So a scene without self-collision never calls stage-07 code, and a student who has not started
// stage 07 runs every other scene.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "clothlab/core/not_implemented.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/sim/simulation.h"

using namespace clothlab;

TEST(Stage07LeftOut, ScenesWithoutSelfCollisionNeverCallStage07) {
    int without = 0, with = 0;
    for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(CLOTHLAB_SOURCE_DIR) / "scenes")) {
        if (e.path().extension() != ".json") continue;
        const Scene scene = loadScene(e.path().string());
        auto sim = makeSimulation(scene);
        if (!scene.self_collision.enabled) {
            ++without;
            EXPECT_NO_THROW(for (int k = 0; k < 5; ++k) sim->step()) << e.path() << " has no self_collision: it must not call stage 07";
        } else {
            ++with;
            try {
                sim->step();
                ADD_FAILURE() << e.path() << " enables self_collision: its first step must reach stage 07's stub";
            } catch (const NotImplemented& x) {
                EXPECT_NE(std::string(x.what()).find("exercise 7."), std::string::npos) << e.path() << ": " << x.what();
            }
        }
    }
    EXPECT_GT(without, 5) << "the scenes without self_collision that ran";
    EXPECT_GE(with, 1) << "the scenes with self_collision (scenes/pbd_self_collision.json)";
}
