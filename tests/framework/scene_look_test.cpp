// The lecture scenes look right, checked by numbers (sim/scene_checks.h; not graded):
//   - a cloth that comes to rest on a collider has no triangle through the collider's surface as it
//     is drawn (the tablecloth over the table's rim, the poncho on the dummy's shoulders, ...);
//   - a cloth hanging from pins keeps the side it shows: no triangle turned against the rest shape's
//     normal (the hammock hangs flat between its hooks, untwisted).
// Each check is proved able to fail: on triangles built here (one through a box, a sphere, a plane; a
// strip twisted by half a turn) and on the scenes themselves with a planted regression: the
// tablecloth at thickness 0 and the hammock with a twisted pin order (the right hooks swapped).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "clothlab/core/grid.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/sim/run.h"
#include "clothlab/sim/scene_checks.h"
#include "clothlab/sim/simulation.h"

using namespace clothlab;
namespace fs = std::filesystem;

namespace {

std::string scenePath(const std::string& name) { return std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/" + name + ".json"; }

// Runs a scene for its solver.steps (at most `max_seconds` of simulated time) and returns the checks at the end.
LookChecks settle(const std::string& name, const std::vector<std::string>& sets = {}, double max_seconds = 6.0) {
    const Scene s = loadScene(scenePath(name), sets);
    auto sim = makeSimulation(s);
    const long long steps = std::min<long long>(s.solver.steps, std::llround(max_seconds / s.solver.dt));
    const RunResult r = runSimulation(*sim, steps, steps);
    EXPECT_FALSE(r.unstable) << name << ": " << r.message;
    return lookChecks(*sim);
}

Eigen::Matrix3d tri(const Vec3& a, const Vec3& b, const Vec3& c) {
    Eigen::Matrix3d m;
    m << a, b, c;
    return m;
}

// A 2 x n strip along x, `width` wide across z, turned about the x axis by `twist` radians from one end to the other.
Matrix3X strip(int n, double twist) {
    Matrix3X x(3, 2 * n);
    for (int c = 0; c < n; ++c) {
        const double a = twist * c / (n - 1);
        for (int r = 0; r < 2; ++r) x.col(r * n + c) = Vec3(0.1 * c, 0, 0) + (r - 0.5) * 0.3 * Vec3(0, -std::sin(a), std::cos(a));
    }
    return x;
}

}  // namespace

TEST(SceneChecks, TrianglesIntersectOnlyWhenTheyShareAPoint) {
    const Eigen::Matrix3d flat = tri(Vec3(-1, 0, -1), Vec3(1, 0, -1), Vec3(0, 0, 1));
    EXPECT_TRUE(trianglesIntersect(flat, tri(Vec3(0, -1, 0), Vec3(0, 1, 0), Vec3(0.1, 1, 0.1)))) << "a triangle through the plane of the other, inside it";
    EXPECT_FALSE(trianglesIntersect(flat, tri(Vec3(0, 0.01, 0), Vec3(0, 1, 0), Vec3(0.1, 1, 0.1)))) << "1 cm above it";
    EXPECT_FALSE(trianglesIntersect(flat, tri(Vec3(3, -1, 0), Vec3(3, 1, 0), Vec3(3.1, 1, 0.1)))) << "through its plane, beside it";
    EXPECT_TRUE(trianglesIntersect(tri(Vec3(0, -1, 0), Vec3(0, 1, 0), Vec3(0.1, 1, 0.1)), flat)) << "either order";
}

TEST(SceneChecks, ATriangleThroughABoxASphereOrAPlaneIsCounted) {
    // Three triangles 2 cm above the collider's top at y = 0, then one corner of the middle one pushed 1 cm into it.
    Matrix3X x(3, 5);
    x << -0.2, -0.1, 0.0, 0.1, 0.2,  //
        0.02, 0.02, 0.02, 0.02, 0.02,  //
        0.0, 0.1, 0.0, 0.1, 0.0;
    const std::vector<Eigen::Vector3i> t = {{0, 1, 2}, {1, 3, 2}, {2, 3, 4}};
    Collider box;
    box.type = Collider::Type::Box;
    box.point = Vec3(0, -0.5, 0), box.halfExtents = Vec3(1, 0.5, 1);
    Collider sphere;
    sphere.type = Collider::Type::Sphere;
    sphere.point = Vec3(0, -1, 0), sphere.radius = 1;
    Collider plane;
    plane.type = Collider::Type::Plane;
    plane.point = Vec3(0, 0, 0), plane.normal = Vec3(0, 1, 0);
    for (const Collider* c : {&box, &sphere, &plane}) {
        EXPECT_TRUE(trianglesThroughCollider(x, t, *c).empty()) << colliderTypeName(c->type) << ": every triangle is above it";
        Matrix3X into = x;
        into(1, 2) = -0.01;  // particle 2 (a corner of all three) 1 cm inside
        EXPECT_EQ(trianglesThroughCollider(into, t, *c).size(), 3u) << colliderTypeName(c->type) << ": the three triangles at particle 2 pass through it";
    }
    // The triangles the renderer draws, not the distance: a triangle across a sharp rim whose corners are all outside.
    Matrix3X rim(3, 3);
    rim << -0.05, 1.02, 1.02,  //
        0.01, -0.05, -0.05,   //
        0.0, -0.05, 0.05;
    EXPECT_EQ(trianglesThroughCollider(rim, {{0, 1, 2}}, box).size(), 1u) << "corners outside the box, the triangle through its edge";
}

TEST(SceneChecks, AHalfTwistTurnsHalfTheStripOver) {
    const int n = 31;
    const std::vector<Eigen::Vector3i> t = gridTriangles(n, 2);
    const Vec3 N = restNormal(strip(n, 0), t);
    EXPECT_NEAR(std::abs(N.y()), 1.0, 1e-12) << "a flat strip in the x-z plane has the normal ±y";
    const NormalFlips flat = normalFlips(strip(n, 0), t, N);
    EXPECT_EQ(flat.flipped, 0) << "a flat strip turns nothing over";
    EXPECT_EQ(flat.triangles, static_cast<int>(t.size()));
    const NormalFlips half = normalFlips(strip(n, M_PI), t, N);
    EXPECT_GT(half.flipped, static_cast<int>(0.4 * t.size())) << "a half twist turns about half the triangles over";
    EXPECT_LT(half.lowest, -0.9) << "and its far end shows the other side";
}

// The tablecloth over the table's sharp rim: with a thickness h above half its edges' length (h = 2.7 cm,
// docs/scenes.md "Colliders") no cloth triangle passes through the table at rest. At thickness 0 they cut it.
TEST(LectureScenes, TableclothRestsWithNoTriangleThroughTheTable) {
    const LookChecks c = settle("pbd_tablecloth");
    ASSERT_TRUE(c.through_applies);
    EXPECT_EQ(c.through, 0) << c.through << " of " << c.triangles << " cloth triangles through the table or the floor at rest";
    const LookChecks planted = settle("pbd_tablecloth", {"solver.thickness=0"});
    EXPECT_GT(planted.through, 0) << "planted regression: at thickness 0 the cloth's triangles should cut the table";
}

// The hammock hangs flat: its corners lifted onto the hooks (not pushed 0.5 m inward in its own
// plane, which buckles the strip sideways through its diagonal constraints and twists it).
TEST(LectureScenes, HammockHangsUntwistedWithItsCornersOnTheHooks) {
    const Scene s = loadScene(scenePath("pbd_hammock"));
    auto sim = makeSimulation(s);
    const RunResult r = runSimulation(*sim, s.solver.steps, s.solver.steps);
    ASSERT_FALSE(r.unstable) << r.message;
    const LookChecks c = lookChecks(*sim);
    ASSERT_TRUE(c.flips_applies);
    EXPECT_EQ(c.flips.flipped, 0) << c.flips.flipped << " of " << c.flips.triangles << " triangles turned over: the strip twists";
    EXPECT_GT(c.flips.lowest, 0.1) << "every triangle's normal agrees with the hooks' plane's (none near vertical)";
    ASSERT_EQ(s.cloth.moves.size(), 4u);
    for (const PinMove& m : s.cloth.moves)
        EXPECT_LT((sim->state().x.col(m.index) - m.to).norm(), 1e-12) << "corner " << m.index << " is on its hook";
    // Planted regression: the right end's two hooks swapped, the strip must turn by half a turn.
    const std::string twisted = R"(cloth.pins=[{"nearest": [-1.5, 1.5, -0.15], "to": [-1, 2, -0.15]}, {"nearest": [-1.5, 1.5, 0.15], "to": [-1, 2, 0.15]},
        {"nearest": [1.5, 1.5, -0.15], "to": [1, 2, 0.15]}, {"nearest": [1.5, 1.5, 0.15], "to": [1, 2, -0.15]}])";
    const LookChecks bad = settle("pbd_hammock", {twisted});
    EXPECT_GT(bad.flips.flipped, 0) << "planted regression: with a twisted pin order the check should see the strip turned over";
}

// Every shipped scene, where the checks apply: resting on its colliders without a triangle through
// them, hanging from its pins without turning over (scenes with wind or colliders may fold: no flip check).
class EveryScene : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryScene, RestsWithoutInterpenetrationOrTwist) {
    const LookChecks c = settle(GetParam());
    if (c.through_applies) {
        EXPECT_EQ(c.through, 0) << GetParam() << ": " << c.through << " of " << c.triangles << " triangles through a collider";
    }
    if (c.flips_applies) {
        EXPECT_EQ(c.flips.flipped, 0) << GetParam() << ": " << c.flips.flipped << " of " << c.flips.triangles << " triangles turned over";
    }
}

std::vector<std::string> shippedScenes() {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(std::string(CLOTHLAB_SOURCE_DIR) + "/scenes"))
        if (e.path().extension() == ".json") names.push_back(e.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

INSTANTIATE_TEST_SUITE_P(Shipped, EveryScene, ::testing::ValuesIn(shippedScenes()),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });
