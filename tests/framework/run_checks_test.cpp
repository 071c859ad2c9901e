// The run checks of run.h fire where a result is not a result, with the step where it started, and
// say it in the one text every program shows. (That they stay silent on every shipped scene is
// SceneClaims.* in scene_claims_test.cpp; the exit code 3 of --strict is in cli_test.sh.)
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>

#include <gtest/gtest.h>

#include "clothlab/io/report.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/sim/colliders.h"
#include "clothlab/sim/run.h"
#include "clothlab/study/theory.h"
#include "test_util.h"

using namespace clothlab;

namespace {

Scene load(const std::string& name, const std::vector<std::string>& sets) {
    return loadScene(std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/" + name, sets);
}

const RunWarning* find(const RunResult& r, WarningKind k) {
    for (const RunWarning& w : r.warnings)
        if (w.kind == k) return &w;
    return nullptr;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

// A 128 x 128 pbd_hanging with its default 10 iterations: the Gauss-Seidel sweep moves a correction
// about one edge per iteration, so 10 iterations cannot hold 128 rows: the cloth stretches like a
// falling sheet. The warning says so, with the step, and names what helps.
TEST(RunChecks, NotConvergedFiresOnA128ClothWithTenIterations) {
    auto sim = makeSimulation(load("pbd_hanging.json", {"cloth.nx=128", "cloth.ny=128"}));
    const RunResult r = runSimulation(*sim, 40, 40);
    ASSERT_FALSE(r.unstable) << r.message;
    const RunWarning* w = find(r, WarningKind::NotConverged);
    ASSERT_NE(w, nullptr) << "a 128^2 cloth at 10 iterations must be reported as not converged";
    EXPECT_GT(w->value, kNotConvergedRmsStrain) << "the RMS strain it reports";
    EXPECT_GE(w->step, 1);
    EXPECT_LE(w->step, 40 - std::lround(kNotConvergedDuration / 0.01) + 1) << "it started early enough to have lasted 0.1 s";
    const std::string text = warningText(*w, sim->scene());
    EXPECT_TRUE(contains(text, "not converged") && contains(text, "step " + std::to_string(w->step)) &&
                contains(text, "solver.iterations (now 10)") && contains(text, "xpbd"))
        << text;
    // The same cloth at 20 x 20 (the scene as shipped) converges: no warning.
    auto small = makeSimulation(load("pbd_hanging.json", {}));
    EXPECT_EQ(find(runSimulation(*small, 40, 40), WarningKind::NotConverged), nullptr);
}

// pbd_sphere at three times its step falls through the sphere. The step it is flagged at is the
// first step in which some particle that started outside the sphere moved along a path reaching
// D = max(4 h, 1 mm) inside it, found here by brute force (1000 points per path).
TEST(RunChecks, FellThroughTheSphereAtThreeTimesItsStep) {
    const Scene scene = load("pbd_sphere.json", {"solver.dt=0.03"});
    const Collider& c = scene.colliders.at(0);
    const double D = std::max(4 * scene.solver.thickness, 1e-3);
    auto probe = makeSimulation(scene);
    long long first = 0;
    for (long long n = 1; n <= 300 && first == 0; ++n) {
        const Matrix3X x0 = probe->state().x;
        probe->step();
        for (int i = 0; i < x0.cols() && first == 0; ++i)
            for (int k = 0; k <= 1000 && first == 0; ++k) {
                const Vec3 p = x0.col(i) + (k / 1000.0) * (probe->state().x.col(i) - x0.col(i));
                if ((p - c.point).norm() - c.radius < -D) first = n;
            }
    }
    ASSERT_GT(first, 0) << "the cloth must pass into the sphere at dt = 0.03 s";

    auto sim = makeSimulation(scene);
    const RunResult r = runSimulation(*sim, 300, 300);
    const RunWarning* w = find(r, WarningKind::FellThrough);
    ASSERT_NE(w, nullptr) << "falling through the sphere must be flagged";
    EXPECT_EQ(w->step, first) << "the step where the first particle went through";
    EXPECT_GT(w->count, 0);
    EXPECT_EQ(r.warnings.front().kind, WarningKind::FellThrough) << "the most severe warning comes first";
    const std::string text = warningText(*w, scene);
    EXPECT_TRUE(contains(text, "fell through") && contains(text, "collider 0 (sphere)") &&
                contains(text, "at step " + std::to_string(first)) && contains(text, "smaller solver.dt"))
        << text;
    // The worst penetration is over the whole run: the cloth ends far below the sphere, its last
    // state touches nothing, but on its way through it was deep inside.
    EXPECT_GT(r.worst_penetration, D) << "worst penetration over the run, m";
    double last = 0;
    for (int i = 0; i < sim->state().size(); ++i)
        last = std::max(last, scene.solver.thickness - colliderDistance(c, sim->state().x.col(i)));
    EXPECT_LT(last, r.worst_penetration) << "the last state alone hides it";
    std::ostringstream summary;
    printSummary(summary, *sim, r);
    EXPECT_TRUE(contains(summary.str(), "worst_penetration") && contains(summary.str(), "warning: fell through")) << summary.str();
}

// One iteration per step cannot hold the cloth on the sphere: particles end steps deep inside it.
TEST(RunChecks, PenetrationFiresWithOneIteration) {
    const Scene scene = load("pbd_sphere.json", {"solver.iterations=1"});
    auto sim = makeSimulation(scene);
    const RunResult r = runSimulation(*sim, 300, 300);
    const RunWarning* w = find(r, WarningKind::Penetration);
    ASSERT_NE(w, nullptr);
    EXPECT_GT(w->value, kPenetrationFactor * scene.solver.thickness);
    EXPECT_LE(w->value, r.worst_penetration) << "the run's worst penetration includes the particles that fell through";
}

// Explicit Euler adds energy every step: (1 + ω²Δt²) per step in the oscillation's energy. On the
// spring scene (ω = 10 rad/s, Δt = 1 ms) that passes 0.1 E_scale within the 5000 steps.
TEST(RunChecks, EnergyGrowthFiresOnExplicitEuler) {
    auto sim = makeSimulation(load("spring.json", {"solver.method=explicit_euler"}));
    const RunResult r = runSimulation(*sim, 5000, 5000);
    const RunWarning* w = find(r, WarningKind::EnergyGrowth);
    ASSERT_NE(w, nullptr);
    EXPECT_GT(w->value, kEnergyGrowthBound);
    EXPECT_GT(w->step, 1) << "it grows gradually";
    auto symplectic = makeSimulation(load("spring.json", {}));
    EXPECT_TRUE(runSimulation(*symplectic, 5000, 5000).warnings.empty()) << "symplectic Euler keeps the energy";
}

// Oscillation is not growth. Every force-based integrator, on the single spring (k = 1e6 N/m,
// ω = 1000 rad/s) and on the hanging mass-spring cloth without damping, at a Δt theory calls stable
// (half its critical step; explicit Euler has none) and one it calls unstable (1.5 times it; explicit
// Euler at every Δt; implicit Euler at none): a stable run gets no EnergyGrowth warning and does not
// stop, an unstable one stops or is warned about. Theory: theoreticalCriticalDt() of ω_max
// (maxAngularFrequency(), an eigenvalue computation, not a run).
TEST(RunChecks, EnergyVerdictFollowsTheoryForEveryIntegrator) {
    struct Case { std::string scene; std::vector<std::string> sets; };
    const std::vector<Case> cases = {
        {"spring.json", {"spring.k=1e6"}},
        {"mfn_hanging.json", {"springs.structural.kd=0", "springs.shear.kd=0", "forces.air_damping=0"}}};
    for (const Case& c : cases)
        for (Method m : {Method::ExplicitEuler, Method::SymplecticEuler, Method::VelocityVerlet, Method::Rk4, Method::ImplicitEuler}) {
            std::vector<std::string> sets = c.sets;
            sets.push_back(std::string("solver.method=") + methodName(m));
            const double omega = maxAngularFrequency(load(c.scene, sets));
            ASSERT_GT(omega, 0.0);
            const double crit = theoreticalCriticalDt(m, omega);
            const double base = theoreticalCriticalDt(Method::SymplecticEuler, omega);  // 2/ω
            struct Run { double dt; bool stable; };
            const std::vector<Run> runs = m == Method::ExplicitEuler   ? std::vector<Run>{{0.5 * base, false}}
                                        : m == Method::ImplicitEuler ? std::vector<Run>{{0.5 * base, true}, {10 * base, true}}
                                                                     : std::vector<Run>{{0.5 * crit, true}, {1.5 * crit, false}};
            for (const Run& run : runs) {
                std::vector<std::string> s2 = sets;
                s2.push_back("solver.dt=" + std::to_string(run.dt));
                auto sim = makeSimulation(load(c.scene, s2));
                const RunResult r = runSimulation(*sim, 2000, 2000);
                const bool warned = find(r, WarningKind::EnergyGrowth) != nullptr;
                const std::string what = c.scene + " " + methodName(m) + " at omega_max dt = " + std::to_string(omega * run.dt);
                if (run.stable)
                    EXPECT_TRUE(!r.unstable && !warned) << what << ": stable by theory, but " << (r.unstable ? r.message : "an energy-growth warning");
                else
                    EXPECT_TRUE(r.unstable || warned) << what << ": unstable by theory, yet the run neither stopped nor warned";
            }
        }
}

// The sheet's question: symplectic Euler at ω Δt = 1 keeps its energy in a band. No warning (so
// --strict passes), no advice to switch to the method in use; a note says how large the bounded
// error is and that a smaller Δt narrows it.
TEST(RunChecks, BoundedSymplecticOscillationGetsANoteNotAWarning) {
    auto sim = makeSimulation(load("spring.json", {"spring.k=1e6", "solver.method=symplectic_euler"}));
    const RunResult r = runSimulation(*sim, 5000, 5000);
    ASSERT_FALSE(r.unstable) << r.message;
    for (const RunWarning& w : r.warnings) ADD_FAILURE() << "a bounded oscillation is no warning: " << warningText(w, sim->scene());
    ASSERT_EQ(r.notes.size(), 1u) << "the energy error above the bound is noted once";
    EXPECT_TRUE(contains(r.notes[0], "bounded") && contains(r.notes[0], "halving solver.dt at least halves it") &&
                !contains(r.notes[0], "symplectic or implicit"))
        << r.notes[0];
    std::ostringstream summary;
    printSummary(summary, *sim, r);
    EXPECT_TRUE(contains(summary.str(), "note: energy error") && !contains(summary.str(), "warning")) << summary.str();
    // The growth warning's advice fits the method: explicit Euler is told of the symplectic methods,
    // symplectic Euler of the step size only.
    auto ee = makeSimulation(load("spring.json", {"solver.method=explicit_euler"}));
    const RunResult re = runSimulation(*ee, 5000, 5000);
    ASSERT_NE(find(re, WarningKind::EnergyGrowth), nullptr);
    EXPECT_TRUE(contains(warningText(*find(re, WarningKind::EnergyGrowth), ee->scene()), "symplectic_euler"));
    RunWarning w;
    w.kind = WarningKind::EnergyGrowth;
    EXPECT_FALSE(contains(warningText(w, sim->scene()), "symplectic_euler, velocity_verlet")) << warningText(w, sim->scene());
}

// A particle that leaves the region |x| < report.blowup stops the run with that cause, and every
// text says so: not "no longer finite" (its state is finite).
TEST(RunChecks, LeftTheRegionSaysSo) {
    auto sim = makeSimulation(load("spring.json", {"report.blowup=1.4"}));  // the particle starts 1.5 m from the origin
    const RunResult r = runSimulation(*sim, 10, 1);
    ASSERT_TRUE(r.unstable);
    EXPECT_EQ(r.cause, StopCause::LeftRegion);
    EXPECT_TRUE(sim->state().isFinite());
    EXPECT_TRUE(contains(r.message, "unstable at step 1 ") && contains(r.message, "left the region |x| < 1.4 m")) << r.message;
    std::ostringstream summary;
    printSummary(summary, *sim, r);
    // The reason once: in the message (the error line), not again in the summary.
    EXPECT_FALSE(contains(summary.str(), "left the region")) << summary.str();
    EXPECT_TRUE(contains(summary.str(), "stopped early, at step 1")) << summary.str();
    EXPECT_FALSE(contains(summary.str(), "no longer finite")) << summary.str();
    EXPECT_STREQ(causeName(r.cause), "left_region");
}

// The path test of the fell-through check finds a path through a sphere whose two ends are both
// outside it, and none for a path that only grazes the thickness band.
TEST(RunChecks, PathDistanceFindsATunnel) {
    Collider s;
    s.type = Collider::Type::Sphere;
    s.point = Vec3(0, 0, 0), s.radius = 0.4;
    EXPECT_LT(pathDistance(s, Vec3(0, 1, 0), Vec3(0, -1, 0), 0.3), -0.3) << "straight through the centre: depth R = 0.4";
    EXPECT_GT(pathDistance(s, Vec3(0, 1, 0), Vec3(0, -1, 0), 0.5), -0.4 - 1e-12) << "never deeper than the deepest point";
    EXPECT_LT(pathDistance(s, Vec3(0.1, 1, 0), Vec3(0.1, -1, 0), 0.04), -0.04) << "through, off centre";
    EXPECT_GT(pathDistance(s, Vec3(0.395, 1, 0), Vec3(0.395, -1, 0), 0.04), -0.04) << "grazing the rim: less than D deep";
    Collider p;  // the ground plane y = 0
    EXPECT_NEAR(pathDistance(p, Vec3(0, 0.01, 0), Vec3(3, 0.02, 0), 0.04), 0.01, 1e-12) << "sliding along the plane";
}

// The instructor's grade of a measurement refuses a number from a run that warned (tests/test_util.h:
// runScene, runGaveAResult, gradeMeasurement): pbd_sphere at dt = 0.03 s falls through the sphere, and
// the grade of a number entered exactly as that run made it still fails, naming the run and its warning;
// the same scene at its own dt gives a result, and the same number then earns the points.
TEST(RunChecks, AGradedMeasurementFromARunThatWarnedIsRefused) {
    std::ifstream in(std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/pbd_sphere.json");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string dir = ::testing::TempDir() + "clothlab_warned_run";
    std::filesystem::create_directories(dir);
    auto grade = [&](const testing_util::SceneRun& run) {
        const double value = run.metric("max_strain");
        std::ofstream(dir + "/answers.json") << "{\"predict\": {}, \"measure\": {\"max_strain\": {\"value\": " << std::setprecision(17) << value
                                             << ", \"how\": \"the run\"}}, \"explain\": \"\"}";
        ::setenv("CLOTHLAB_ANSWERS_DIR", dir.c_str(), 1);
        const testing::AssertionResult g =
            testing_util::gradeMeasurement("09_none", "max_strain", value, 1e-9, testing_util::runGaveAResult(run), "max_strain");
        ::unsetenv("CLOTHLAB_ANSWERS_DIR");
        return g;
    };
    const testing_util::SceneRun warned = testing_util::runScene(text.c_str(), "scenes/pbd_sphere.json", {"solver.dt=0.03", "solver.steps=60"});
    ASSERT_FALSE(warned.warning.empty()) << "pbd_sphere at dt = 0.03 s must warn (it falls through the sphere): the test needs a run that warns";
    const testing::AssertionResult refused = grade(warned);
    EXPECT_FALSE(refused) << "a measurement from a run that warned must earn no points";
    EXPECT_NE(std::string(refused.message()).find("warned (" + warned.warning + ")"), std::string::npos)
        << "the refusal must name the run's warning; it says: " << refused.message();
    EXPECT_NE(std::string(refused.message()).find("./lab run scenes/pbd_sphere.json --set solver.dt=0.03"), std::string::npos)
        << "the refusal must name the run; it says: " << refused.message();
    const testing_util::SceneRun clean = testing_util::runScene(text.c_str(), "scenes/pbd_sphere.json", {"solver.steps=60"});
    EXPECT_TRUE(clean.warning.empty()) << "pbd_sphere at its own dt must not warn: " << clean.warning;
    EXPECT_TRUE(grade(clean)) << "the same number from a run without a warning must earn the points";
}
