// Scenes that describe any cloth (framework, not graded): mesh cloths from OBJ files, grids at any
// orientation, pins by index, nearest point or box and moved to a position, a chain between two anchors,
// and the catenary it hangs in. Expected values come from geometry computed here, not from the loader.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <map>

#include <gtest/gtest.h>

#include "clothlab/core/grid.h"
#include "clothlab/core/input_error.h"
#include "clothlab/core/mesh.h"
#include "clothlab/core/topology.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/sim/analytic.h"
#include "clothlab/sim/colliders.h"
#include "clothlab/sim/mass_spring.h"
#include "clothlab/sim/pbd.h"

using namespace clothlab;
namespace fs = std::filesystem;

namespace {

// A fresh folder under the system's temp dir (tests never write into the source tree).
fs::path tempDir() {
    static const fs::path d = [] {
        fs::path p = fs::temp_directory_path() / ("clothlab_mesh_scene_" + std::to_string(::getpid()));
        fs::create_directories(p);
        return p;
    }();
    return d;
}
void writeFile(const std::string& name, const std::string& text) { std::ofstream(tempDir() / name) << text; }
std::string sceneFile() { return (tempDir() / "t.json").string(); }

// The unit square in the x-z plane as two triangles: (0,0) (1,0) (1,1) (0,1), split along 0-2.
const char* kSquare = "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 2 3\nf 1 3 4\n";

std::string meshCloth(const std::string& obj, const std::string& extra = "") {
    return R"({"model": "cloth", "cloth": {"mesh": ")" + obj + R"(", "mass": 1.0)" + extra +
           R"(}, "solver": {"method": "pbd"}, "constraints": {"distance": {}, "bending": {}}})";
}
Scene load(const std::string& text, const std::vector<std::string>& sets = {}) { return parseScene(text, sceneFile(), sets); }
std::string errorOf(const std::string& text, const std::vector<std::string>& sets = {}) {
    try {
        load(text, sets);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}
std::string grid(const std::string& extra) {
    return R"({"model": "cloth", "cloth": {"nx": 3, "ny": 3, "width": 2, "height": 2, "origin": [1, 2, 3])" + extra +
           R"(}, "solver": {"method": "pbd"}, "constraints": {"distance": {}}})";
}

}  // namespace

// ---- mesh cloth -------------------------------------------------------------------------------------

TEST(MeshScene, MeshClothLoadsBesideTheSceneWithLumpedMasses) {
    writeFile("square.obj", kSquare);
    const Scene s = load(meshCloth("square.obj", R"(, "origin": [0, 2, 0], "scale": 2)"));
    ASSERT_TRUE(s.cloth.meshData);
    const ClothGeometry g = makeClothGeometry(s.cloth);
    ASSERT_EQ(g.state.size(), 4);
    EXPECT_EQ(g.triangles.size(), 2u);
    EXPECT_LT((g.state.x.col(2) - Vec3(2, 2, 2)).norm(), 1e-12) << "x = origin + scale * vertex";
    // Each triangle (area 2 after scaling) gives a third of its area to each corner: corners 0 and 2 are in
    // both triangles, 1 and 3 in one: masses 1/3, 1/6, 1/3, 1/6 of the total 1 kg.
    const double expected[4] = {1.0 / 3, 1.0 / 6, 1.0 / 3, 1.0 / 6};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(1.0 / g.state.w[i], expected[i], 1e-12) << "particle " << i;
}

TEST(MeshScene, MeshErrorsNameSceneFieldAndObj) {
    const auto reason = [](const std::string& obj, const std::string& text) {
        writeFile("bad.obj", text);
        (void)obj;
        return errorOf(meshCloth("bad.obj"));
    };
    const std::string prefix = sceneFile() + ": cloth.mesh: " + (tempDir() / "bad.obj").string() + ": ";
    EXPECT_EQ(errorOf(meshCloth("missing.obj")), sceneFile() + ": cloth.mesh: " + (tempDir() / "missing.obj").string() + ": no such file");
    EXPECT_EQ(reason("", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"), prefix + "no faces (a mesh needs at least one triangle)");
    EXPECT_EQ(reason("", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"), prefix + "face 0 (vertices 0, 1, 2) has zero area");
    EXPECT_EQ(reason("", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2\n"), prefix + "face 0 (vertices 0, 1, 1) has zero area");
    EXPECT_EQ(reason("", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n"),
              prefix + "non-manifold edge (0, 1) shared by more than two faces (face 2 (vertices 0, 1, 4) is the third)");
    const std::string range = reason("", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    EXPECT_EQ(range.rfind(prefix, 0), 0u) << range;
    EXPECT_NE(range.find("out of range"), std::string::npos) << range;
    EXPECT_EQ(reason("", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf 1 2 3\n"), prefix + "vertex 3 belongs to no face (it would have no mass)");
    writeFile("square.obj", kSquare);
    EXPECT_EQ(errorOf(meshCloth("square.obj", R"(, "nx": 4)")), sceneFile() + ": cloth.nx: not used by a mesh cloth (cloth.mesh is given)");
    EXPECT_NE(errorOf(meshCloth("square.obj", R"(, "normal": [0, 1, 0])")).find("cloth.normal: not used by a mesh cloth"), std::string::npos);
    EXPECT_NE(errorOf(meshCloth("square.obj", R"(, "pins": ["top-left"])")).find("cloth.pins[0]: named pins need a grid cloth"), std::string::npos);
    EXPECT_NE(errorOf(meshCloth("square.obj", R"(, "scale": 0)")).find("cloth.scale: must be > 0"), std::string::npos);
    EXPECT_NE(errorOf(grid(R"(, "scale": 2)")).find("cloth.scale: only for a mesh cloth"), std::string::npos);
}

TEST(MeshScene, MeshClothRunsInPbdAndMassSpring) {
    const std::string disc = std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/meshes/round_cloth.obj";
    const Scene s = load(meshCloth(disc, R"(, "origin": [0, 1, 0], "pins": [{"nearest": [0, 1, 0]}])"), {"solver.dt=0.01", "solver.iterations=50", "constraints.bending.stiffness=0.001"});
    const ClothGeometry g = makeClothGeometry(s.cloth);
    // Edges and interior edges counted here from the triangles: an edge in two triangles is interior.
    std::map<std::pair<int, int>, int> use;
    for (const auto& t : g.triangles)
        for (int k = 0; k < 3; ++k) ++use[std::minmax(t[k], t[(k + 1) % 3])];
    size_t interior = 0;
    for (const auto& [e, n] : use) interior += n == 2;
    PbdSimulation pbd(s);
    EXPECT_EQ(pbd.distanceLinks().size(), use.size()) << "one distance constraint per mesh edge";
    EXPECT_EQ(pbd.bendingStencilList().size(), interior) << "one bending stencil per interior edge";
    for (int n = 0; n < 100; ++n) pbd.step();
    EXPECT_TRUE(pbd.state().isFinite());
    // Unconstrained, the rim would fall 4.9 m in this second while the centre stays: the edges hold (PBD with
    // 50 iterations still stretches ~10 % next to a single pin).
    EXPECT_LT(pbd.strain().max, 0.2) << "the distance constraints hold the mesh's edge lengths";
    EXPECT_LT(pbd.state().x.row(1).minCoeff(), 0.8) << "held at its centre, the rim falls";

    Scene ms = s;
    ms.solver.method = Method::SymplecticEuler;
    ms.solver.dt = 1e-4;
    ms.springs.structural = {true, 2000.0, 0.5};
    ms.springs.bending = {true, 20.0, 0.0};
    const MassSpringModel m = makeCloth(ms);
    size_t structural = 0, bending = 0;
    for (const Spring& sp : m.springs) (sp.type == SpringType::Structural ? structural : bending) += 1;
    EXPECT_EQ(structural, use.size()) << "a structural spring per edge";
    EXPECT_EQ(bending, oppositeVertices(g.triangles).size());
    EXPECT_GE(bending, interior * 99 / 100) << "about one bending spring per interior edge";
    auto sim = makeSimulation(ms);
    for (int n = 0; n < 500; ++n) sim->step();
    EXPECT_TRUE(sim->state().isFinite());
    EXPECT_LT(sim->state().x.row(1).minCoeff(), 1.0 - 1e-3);
}

// ---- grids at any orientation ------------------------------------------------------------------------

TEST(MeshScene, GridRotationAndNormal) {
    const Scene r = load(grid(R"(, "rotation": [0, 0, 90])"));
    const State s = makeGridState(r.cloth);
    // (c, r) = (1, 0) lies 1 m along +x before the turn; 90 degrees about z takes +x to +y.
    EXPECT_LT((s.x.col(1) - Vec3(1, 3, 3)).norm(), 1e-12);
    // (0, 1) lies 1 m below (−y) before; the turn takes −y to +x.
    EXPECT_LT((s.x.col(3) - Vec3(2, 2, 3)).norm(), 1e-12);

    const Scene n = load(grid(R"(, "normal": [1, 1, 0])"));
    const ClothGeometry g = makeClothGeometry(n.cloth);
    const Vec3 want = Vec3(1, 1, 0).normalized();
    for (const auto& t : g.triangles) {
        const Vec3 m = (g.state.x.col(t[1]) - g.state.x.col(t[0])).cross(g.state.x.col(t[2]) - g.state.x.col(t[0])).normalized();
        EXPECT_LT((m - want).norm(), 1e-12) << "every triangle faces the given normal";
    }
    EXPECT_LT((g.state.x.col(0) - Vec3(1, 2, 3)).norm(), 1e-12) << "turned about the origin";
    const Scene flat = load(grid(R"(, "normal": [0, 1, 0])"));
    const State f = makeGridState(flat.cloth);
    EXPECT_LT((f.x.row(1).array() - 2.0).abs().maxCoeff(), 1e-12) << "normal +y: a horizontal cloth at the origin's height";

    EXPECT_NE(errorOf(grid(R"(, "normal": [0, 0, 0])")).find("cloth.normal: must not be the zero vector"), std::string::npos);
    EXPECT_NE(errorOf(grid(R"(, "normal": [0, 1, 0], "rotation": [0, 0, 0])")).find("cloth.normal: give cloth.rotation or cloth.normal, not both"),
              std::string::npos);
    EXPECT_NE(errorOf(grid(R"(, "rotation": [0, 0])")).find("cloth.rotation: expected an array of 3 numbers"), std::string::npos);
    const Scene old = load(grid(R"(, "orientation": "horizontal", "tilt": 30)"));
    EXPECT_TRUE(old.cloth.horizontal);
    EXPECT_EQ(old.cloth.tilt, 30.0) << "the old fields still work";
}

// ---- pins ---------------------------------------------------------------------------------------------

TEST(MeshScene, PinsByIndexNearestBoxAndMoved) {
    // Grid particles: (c, r) at (1 + c, 2 - r, 3), index 3 r + c.
    const Scene s = load(grid(R"(, "pins": [0, {"index": 2, "to": [5, 5, 5]}, {"nearest": [2.1, 0.2, 3]}, {"box": {"min": [0, 0.5, 0], "max": [1.5, 1.5, 4]}}])"));
    EXPECT_EQ(s.cloth.pins, (std::vector<int>{0, 2, 7, 3})) << "index 0; index 2; nearest to (2.1, 0.2) is (1, 2) = 7; box holds (0, 1) = 3";
    ASSERT_EQ(s.cloth.moves.size(), 1u);
    EXPECT_EQ(s.cloth.moves[0].index, 2);
    const Scene m = load(grid(R"(, "pins": [{"nearest": [3, 2, 3], "to": [2.5, 2, 3]}, 0])"));
    PbdSimulation sim(m);
    EXPECT_LT((sim.state().x.col(2) - Vec3(2.5, 2, 3)).norm(), 1e-12) << "a pin with \"to\" starts there";
    EXPECT_EQ(sim.state().w[2], 0.0);
    for (const DistanceLink& l : sim.distanceLinks())
        EXPECT_NEAR(l.d, l.i / 3 == l.j / 3 || l.i % 3 == l.j % 3 ? 1.0 : std::sqrt(2.0), 1e-12)
            << "rest lengths from the grid at rest, not from the moved pin";
    for (int n = 0; n < 100; ++n) sim.step();
    EXPECT_LT((sim.state().x.col(2) - Vec3(2.5, 2, 3)).norm(), 1e-12) << "and stays there";

    const std::string bad = grid(R"(, "pins": [X])");
    const auto pinError = [&](const std::string& pin) {
        std::string t = bad;
        t.replace(t.find('X'), 1, pin);
        return errorOf(t);
    };
    EXPECT_NE(pinError(R"({"index": 9})").find("cloth.pins[0].index: must be between 0 and 8 (got 9)"), std::string::npos);
    EXPECT_NE(pinError(R"({"index": 1, "nearest": [0, 0, 0]})").find("cloth.pins[0]: give exactly one of index, nearest, box"), std::string::npos);
    EXPECT_NE(pinError(R"({})").find("cloth.pins[0]: give exactly one of index, nearest, box"), std::string::npos);
    EXPECT_NE(pinError(R"({"box": {"min": [9, 9, 9], "max": [10, 10, 10]}})").find("cloth.pins[0].box: no particle lies inside the box"),
              std::string::npos);
    EXPECT_NE(pinError(R"({"box": {"min": [0, 0, 0], "max": [-1, 10, 10]}})").find("cloth.pins[0].box.max: must be >= min"), std::string::npos);
    EXPECT_NE(pinError(R"({"box": {"min": [0, 0, 0]}})").find("cloth.pins[0].box: needs min and max"), std::string::npos);
    EXPECT_NE(pinError(R"({"box": {"min": [0, 0, 0], "max": [9, 9, 9]}, "to": [0, 0, 0]})").find("cloth.pins[0].to: moves one particle"),
              std::string::npos);
    EXPECT_NE(pinError(R"({"index": 1, "to": [0, 0]})").find("cloth.pins[0].to: expected an array of 3 numbers"), std::string::npos);
    EXPECT_NE(pinError(R"({"index": 1, "color": 3})").find("cloth.pins[0].color: unknown key"), std::string::npos);
    EXPECT_NE(pinError("99").find("cloth.pins[0]: particle index 99 outside the cloth (0..8)"), std::string::npos);
}

// ---- a chain between two anchors and its catenary --------------------------------------------------------

TEST(MeshScene, ChainBetweenTwoAnchorsStartsAsAV) {
    const Scene s = load(R"({"model": "chain", "chain": {"particles": 31, "l0": 0.1, "anchor": [-1, 2, 0], "end": [1, 2, 0]}})");
    const MassSpringModel m = makeChain(s.chain);
    EXPECT_LT((m.state.x.col(0) - Vec3(-1, 2, 0)).norm(), 1e-12);
    EXPECT_LT((m.state.x.col(30) - Vec3(1, 2, 0)).norm(), 1e-12);
    EXPECT_EQ(m.state.w[0], 0.0);
    EXPECT_EQ(m.state.w[30], 0.0);
    for (int i = 1; i < 30; ++i) {
        EXPECT_GT(m.state.w[i], 0.0);
        EXPECT_LT(m.state.x(1, i), 2.0) << "below the anchors";
        EXPECT_NEAR((m.state.x.col(i) - m.state.x.col(i - 1)).norm(), 0.1, 1e-12) << "links at rest length";
    }
    EXPECT_NE(errorOf(R"({"model": "chain", "chain": {"particles": 11, "l0": 0.1, "end": [1, 0, 0]}})").find("chain.end: the anchors are 1"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"model": "chain", "chain": {"end": [1, 0]}})").find("chain.end: expected an array of 3 numbers"), std::string::npos);
}

TEST(MeshScene, CatenaryHasTheArcLengthAndEndPoints) {
    for (const Vec3& end : {Vec3(2, 0, 0), Vec3(1.5, 0.7, 1.0)}) {
        Catenary c{Vec3(0, 1, 0), Vec3(0, 1, 0) + end, Vec3(0, 1, 0), 3.0};
        ASSERT_TRUE(c.solve());
        const double d = Vec3(end.x(), 0, end.z()).norm();
        EXPECT_LT((c.at(0) - c.start).norm(), 1e-9);
        EXPECT_LT((c.at(d) - c.end).norm(), 1e-9) << "the curve ends at the second anchor";
        double arc = 0;  // arc length by summing 1e5 chords
        for (int k = 0; k < 100000; ++k) arc += (c.at(d * (k + 1) / 1e5) - c.at(d * k / 1e5)).norm();
        EXPECT_NEAR(arc, 3.0, 1e-6) << "arc length s";
        EXPECT_LT(c.distance(c.at(0.3 * d)), 1e-6);
        const double above = c.distance(c.at(0.3 * d) + Vec3(0, 0.02, 0));  // 2 cm above the curve: at most 2 cm from it
        EXPECT_LE(above, 0.02 + 1e-9);
        EXPECT_GT(above, 0.005);
    }
    Catenary level{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 1, 0), 3.0};
    ASSERT_TRUE(level.solve());
    EXPECT_NEAR(3.0, 2 * level.a * std::sinh(2.0 / (2 * level.a)), 1e-9);
    // The sag a (cosh(d/2a) - 1) of a 3 m chain between level hooks 2 m apart: 1.00527 m (solving
    // 1.5 = a sinh(1/a) separately, by bisection in Python: a = 0.616473 m).
    EXPECT_NEAR(level.a, 0.616473, 1e-5);
    EXPECT_NEAR(-level.at(1.0).y(), 1.00527, 1e-4);
    Catenary tooShort{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 1, 0), 1.9};
    EXPECT_FALSE(tooShort.solve());
}

// ---- collider fields -------------------------------------------------------------------------------------

TEST(MeshScene, ColliderFieldsAndErrors) {
    writeFile("box.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");  // a closed tetrahedron
    const auto withCollider = [](const std::string& c) {
        return R"({"model": "cloth", "solver": {"method": "pbd"}, "colliders": [)" + c + "]}";
    };
    const Scene s = load(withCollider(R"({"type": "box", "center": [1, 2, 3], "half_extents": [0.5, 0.1, 0.2], "rotation": [0, 90, 0], "friction": 0.4},
                                         {"type": "capsule", "start": [0, 0, 0], "end": [0, 3, 0], "radius": 0.05, "restitution": 0.5},
                                         {"type": "mesh", "mesh": "box.obj", "origin": [0, 1, 0], "scale": 2})"));
    ASSERT_EQ(s.colliders.size(), 3u);
    EXPECT_EQ(s.colliders[0].type, Collider::Type::Box);
    EXPECT_LT((s.colliders[0].rotation * Vec3::UnitX() - Vec3(0, 0, -1)).norm(), 1e-12) << "90 degrees about y takes +x to -z";
    EXPECT_EQ(s.colliders[0].friction, 0.4);
    EXPECT_EQ(s.colliders[1].type, Collider::Type::Capsule);
    EXPECT_EQ(s.colliders[1].end, Vec3(0, 3, 0));
    EXPECT_EQ(s.colliders[1].restitution, 0.5);
    ASSERT_EQ(s.colliders[2].type, Collider::Type::Mesh);
    EXPECT_LT((s.colliders[2].shape->mesh().vertices.col(3) - Vec3(0, 1, 2)).norm(), 1e-12) << "origin + scale * vertex";

    const auto err = [&](const std::string& c) { return errorOf(withCollider(c)); };
    EXPECT_NE(err(R"({"type": "box", "half_extents": [1, 0, 1]})").find("colliders[0].half_extents: every half extent must be > 0"), std::string::npos);
    EXPECT_NE(err(R"({"type": "box", "rotation": [1, 2]})").find("colliders[0].rotation: expected an array of 3 numbers"), std::string::npos);
    EXPECT_NE(err(R"({"type": "box", "radius": 1})").find("colliders[0].radius: unknown key"), std::string::npos);
    EXPECT_NE(err(R"({"type": "capsule", "start": [1, 1, 1], "end": [1, 1, 1]})").find("colliders[0].end: equals start"), std::string::npos);
    EXPECT_NE(err(R"({"type": "capsule", "radius": 0})").find("colliders[0].radius: must be > 0"), std::string::npos);
    EXPECT_NE(err(R"({"type": "mesh"})").find("colliders[0].mesh: missing"), std::string::npos);
    EXPECT_NE(err(R"({"type": "mesh", "mesh": "nothing.obj"})").find("colliders[0].mesh: " + (tempDir() / "nothing.obj").string() + ": no such file"),
              std::string::npos);
    EXPECT_NE(err(R"({"type": "mesh", "mesh": "box.obj", "scale": -1})").find("colliders[0].scale: must be > 0"), std::string::npos);
    EXPECT_NE(err(R"({"type": "cone"})").find("colliders[0].type: unknown value \"cone\" (allowed: plane, sphere, box, capsule, mesh)"),
              std::string::npos);
}
