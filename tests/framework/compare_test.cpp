// Methods side by side (study/compare.h; not graded): the --compare list, the error measure a scene
// names, runs advanced together in simulated time, each with its own wall time, and compare.csv with
// one row per run per sample.
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "clothlab/core/input_error.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/study/compare.h"

using namespace clothlab;

namespace {

std::string scenePath(const std::string& name) { return std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/" + name + ".json"; }

std::string tmpDir() {
    const char* t = std::getenv("CLOTHLAB_TEST_TMP");
    std::string dir = t && *t ? t : ::testing::TempDir();
    while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
    return dir;
}

// The InputError text of parseCompare(list) on the spring scene, "" when it parses.
std::string parseError(const std::string& list) {
    try {
        parseCompare(list, scenePath("spring"));
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(Compare, ListOfMethodsAndSettings) {
    const auto v = parseCompare("pbd:iterations=5,pbd:iterations=50:substeps=2,xpbd", scenePath("pbd_hanging"));
    ASSERT_EQ(v.size(), 3u);
    EXPECT_EQ(v[0].label, "pbd:iterations=5");
    EXPECT_EQ(v[0].solver.method, Method::Pbd);
    EXPECT_EQ(v[0].solver.iterations, 5);
    EXPECT_EQ(v[1].solver.iterations, 50);
    EXPECT_EQ(v[1].solver.substeps, 2);
    EXPECT_EQ(v[2].solver.method, Method::Xpbd);
    EXPECT_EQ(v[2].solver.iterations, 10) << "a setting not named keeps the scene's (pbd_hanging: 10 iterations)";
    EXPECT_EQ(v[2].solver.dt, 0.01) << "the scene's dt";
    EXPECT_EQ(compareLabel(v[1].solver, loadScene(scenePath("pbd_hanging")).solver), "pbd:iterations=50:substeps=2");
}

TEST(Compare, BadListsSayWhatIsWrong) {
    EXPECT_NE(parseError("symplectic_euler").find("command line: --compare: expected 2 to 4 runs"), std::string::npos) << parseError("symplectic_euler");
    EXPECT_NE(parseError("rk4,rk4,rk4,rk4,rk4").find("expected 2 to 4 runs"), std::string::npos);
    EXPECT_NE(parseError("rk4,,rk4").find("an empty run"), std::string::npos);
    EXPECT_NE(parseError("rk4,rk4:dt").find("expected METHOD:key=value"), std::string::npos) << parseError("rk4,rk4:dt");
    EXPECT_NE(parseError("rk4,rk4:forces.gravity=0").find("a key of solver"), std::string::npos);
    EXPECT_NE(parseError("rk4,rk5").find("\"rk5\": "), std::string::npos) << parseError("rk4,rk5");
    EXPECT_NE(parseError("rk4,rk5").find("solver.method: unknown value"), std::string::npos) << "the loader's reason";
    EXPECT_NE(parseError("rk4,rk4:dt=-1").find("solver.dt: must be > 0"), std::string::npos) << parseError("rk4,rk4:dt=-1");
    EXPECT_EQ(parseError("rk4,explicit_euler:dt=0.0005"), "");
}

TEST(Compare, TheScenesErrorMeasure) {
    const auto measureOf = [](const std::string& name, const std::vector<std::string>& sets = {}) {
        const Scene s = loadScene(scenePath(name), sets);
        return compareMeasure(s, makeSimulation(s)->metrics());
    };
    EXPECT_EQ(measureOf("spring").name, "error") << "the analytic solution where there is one";
    EXPECT_EQ(measureOf("spring").unit, "m");
    EXPECT_EQ(measureOf("chain_catenary").name, "catenary_error");
    EXPECT_EQ(measureOf("pbd_hanging").name, "rms_strain");
    EXPECT_EQ(measureOf("pbd_hanging").unit, "1");
    EXPECT_EQ(measureOf("pbd_hanging", {"view.error=energy_drift"}).name, "energy_drift") << "the scene names one";
    EXPECT_THROW(measureOf("pbd_hanging", {"view.error=nonsense"}), InputError);
}

// Explicit against symplectic Euler on the single spring (k = 100 N/m, m = 1 kg, dt = 1 ms): the runs
// reach the same times together; explicit Euler's energy grows, so its error ends above symplectic's.
TEST(Compare, RunsGoTogetherAndTheCsvHasARowPerRunPerSample) {
    const Scene s = loadScene(scenePath("spring"));
    Comparison c(s, parseCompare("explicit_euler,symplectic_euler", scenePath("spring")));
    ASSERT_EQ(c.runs().size(), 2u);
    EXPECT_EQ(c.measure().name, "error");
    c.sample();
    const int samples = 20;
    for (int k = 1; k <= samples; ++k) {
        c.advanceTo(0.1 * k);
        c.sample();
        for (const CompareRun& r : c.runs()) EXPECT_NEAR(r.sim->state().t, 0.1 * k, 1e-9) << r.variant.label << " at sample " << k;
    }
    for (const CompareRun& r : c.runs()) {
        ASSERT_EQ(r.samples.size(), static_cast<size_t>(samples + 1));
        EXPECT_EQ(r.steps, 2000) << "2 s at dt = 1 ms";
        EXPECT_GT(r.wall, 0.0);
        EXPECT_GE(r.samples.back().wall, r.samples[samples / 2].wall) << "the wall time only grows";
        EXPECT_GT(r.samples.back().step_ms, 0.0);
    }
    EXPECT_GT(c.runs()[0].samples.back().energy, c.runs()[1].samples.back().energy) << "explicit Euler gains energy";
    EXPECT_GT(std::abs(c.runs()[0].samples.back().error), std::abs(c.runs()[1].samples.back().error))
        << "and ends further from the exact solution";

    const std::string path = tmpDir() + "/compare_test.csv";
    writeCompareCsv(path, c);
    std::ifstream in(path);
    std::string line;
    ASSERT_TRUE(std::getline(in, line));
    EXPECT_EQ(line, "method,t [s],wall [s],error [m],energy [J],max_strain [1]");
    std::map<std::string, int> rows;
    std::map<std::string, double> last_t;
    while (std::getline(in, line)) {
        std::stringstream ss(line);
        std::string method, t;
        std::getline(ss, method, ',');
        std::getline(ss, t, ',');
        ++rows[method];
        last_t[method] = std::stod(t);
        EXPECT_NE(line.find(",nan"), std::string::npos) << "the spring has no edges: max strain nan (" << line << ")";
    }
    EXPECT_EQ(rows["explicit_euler"], samples + 1);
    EXPECT_EQ(rows["symplectic_euler"], samples + 1);
    EXPECT_EQ(rows.size(), 2u);
    EXPECT_NEAR(last_t["explicit_euler"], 2.0, 1e-9);
}

// A run that blows up stops with its message; the other goes on (the lecture's point).
TEST(Compare, AnUnstableRunStopsAloneWithItsMessage) {
    const Scene s = loadScene(scenePath("spring"));
    Comparison c(s, parseCompare("explicit_euler:dt=0.2,symplectic_euler", scenePath("spring")));
    c.advanceTo(60.0);
    c.sample();
    EXPECT_TRUE(c.runs()[0].stopped());
    EXPECT_EQ(c.runs()[0].message.rfind("unstable at step", 0), 0u) << c.runs()[0].message;
    EXPECT_FALSE(c.runs()[1].stopped());
    EXPECT_NEAR(c.runs()[1].sim->state().t, 60.0, 1e-6) << "the stable run reaches the time";
    EXPECT_NEAR(c.time(), 60.0, 1e-6) << "the common time is the running runs'";
}
