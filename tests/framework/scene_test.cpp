// Scene loading and validation (framework, not graded).
#include <gtest/gtest.h>

#include "clothlab/core/input_error.h"
#include "clothlab/io/scene_json.h"

using namespace clothlab;

namespace {
std::string errorOf(const std::string& text, const std::vector<std::string>& sets = {}) {
    try {
        parseScene(text, "t.json", sets);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(Scene, DefaultsAndOverrides) {
    const Scene s = parseScene(R"({"model": "spring", "spring": {"k": 50}})", "t.json", {"solver.dt=0.02", "spring.mass=2"});
    EXPECT_EQ(s.spring.k, 50.0);
    EXPECT_EQ(s.spring.mass, 2.0);
    EXPECT_EQ(s.solver.dt, 0.02);
    EXPECT_EQ(s.solver.method, Method::SymplecticEuler);
    EXPECT_FALSE(s.springs.structural.enabled) << "a scene names what it uses; nothing else is on";
    EXPECT_TRUE(s.colliders.empty());
}

TEST(Scene, ErrorsNameFileAndField) {
    EXPECT_EQ(errorOf(R"({"model": "spring", "spring": {"mass": -1}})"), "t.json: spring.mass: must be > 0 (got -1)");
    EXPECT_EQ(errorOf(R"({"model": "spring", "solver": {"steps": 1.5}})"),
              "t.json: solver.steps: expected a whole number (got number 1.5)");
    EXPECT_NE(errorOf(R"({"model": "spring", "spring": {"k": 1}, "extra": 1})").find("t.json: extra: unknown key"), std::string::npos);
    EXPECT_NE(errorOf(R"({"model": "spring"})", {"spring.k=NaN"}).find("t.json: spring.k: expected a number"), std::string::npos);
    EXPECT_NE(errorOf(R"({"model": "spring"})", {"noequals"}).find("--set expects key=value"), std::string::npos);
    EXPECT_NE(errorOf(R"({"model": "cloth", "cloth": {"nx": 3, "ny": 3, "pins": ["middle"]}})").find("cloth.pins[0]: unknown pin"),
              std::string::npos);
}

TEST(Scene, ClothPinsByName) {
    const Scene s = parseScene(R"({"model": "cloth", "cloth": {"nx": 4, "ny": 3, "pins": ["top-left", "top-right", "bottom-right", 5]}})",
                               "t.json");
    EXPECT_EQ(s.cloth.pins, (std::vector<int>{0, 3, 11, 5}));
}

TEST(Scene, CollidersAreNormalised) {
    const Scene s = parseScene(R"({"model": "cloth", "colliders": [{"type": "plane", "normal": [0, 2, 0]},
                                                                   {"type": "sphere", "center": [0, 1, 0], "radius": 0.3}]})",
                               "t.json");
    ASSERT_EQ(s.colliders.size(), 2u);
    EXPECT_DOUBLE_EQ(s.colliders[0].normal.norm(), 1.0);
    EXPECT_EQ(s.colliders[1].type, Collider::Type::Sphere);
    EXPECT_DOUBLE_EQ(s.colliders[1].radius, 0.3);
}

TEST(Scene, EveryShippedSceneLoads) {
    for (const char* name : {"spring", "chain"}) {
        EXPECT_NO_THROW(loadScene(std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/" + name + ".json")) << name;
    }
}

#include "clothlab/core/grid.h"

TEST(Grid, MassesPinsAndTriangles) {
    ClothSpec c;
    c.nx = 4, c.ny = 3, c.mass = 2.4, c.width = 3.0, c.height = 1.0, c.pins = {0, 3};
    const State s = makeGridState(c);
    ASSERT_EQ(s.size(), 12);
    EXPECT_DOUBLE_EQ(s.w[5], 12 / 2.4);
    EXPECT_EQ(s.w[0], 0.0);
    EXPECT_EQ(s.w[3], 0.0);
    EXPECT_TRUE(s.x.col(gridIndex(3, 2, 4)).isApprox(Vec3(3.0, -1.0, 0.0)));
    const auto tris = gridTriangles(4, 3);
    EXPECT_EQ(tris.size(), 12u);
    // Counter-clockwise seen from +z: the normal of every triangle of a vertical cloth points to +z.
    for (const auto& t : tris) {
        const Vec3 n = (s.x.col(t[1]) - s.x.col(t[0])).cross(s.x.col(t[2]) - s.x.col(t[0]));
        EXPECT_GT(n.z(), 0.0);
    }
}
