// The solver's threads (sim/team.h): runShares() runs every share once and passes exceptions on,
// TeamCap limits the team, AdaptiveTeam keeps the faster size by its rule (driven here with made-up
// times, so the test does not depend on the machine's speed or load), and the default
// solver.threads = 0, switching between one and two threads while it runs, gives the serial run's
// state bit for bit. No test here asserts a speed: benchmarks/threads_under_load.sh shows that.
#include <atomic>
#include <chrono>
#include <cstring>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

#include <gtest/gtest.h>

#include "clothlab/io/scene_json.h"
#include "clothlab/sim/mass_spring.h"
#include "clothlab/sim/pbd.h"
#include "clothlab/sim/team.h"

using namespace clothlab;

namespace {
Scene scene(const std::string& name, std::vector<std::string> sets) {
    return loadScene(std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/" + name + ".json", sets);
}

bool bitIdentical(const Matrix3X& a, const Matrix3X& b) {
    return a.cols() == b.cols() &&
           std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<size_t>(a.size())) == 0;
}

// Drives a team with made-up unit times: `seconds(size)` for a unit of that size, `units` units.
template <class Seconds>
void drive(AdaptiveTeam& team, int units, const Seconds& seconds) {
    for (int k = 0; k < units; ++k) team.record(seconds(team.threads()));
}

// Sets what solver.threads = 0 allows (ctest runs the tests with OMP_NUM_THREADS=1), for one test.
struct DefaultThreads {
    explicit DefaultThreads(int n) { setDefaultThreads(n); }
    ~DefaultThreads() { setDefaultThreads(0); }
};
}  // namespace

TEST(Threads, RunSharesRunsEveryShareOnceOnItsOwnThread) {
    for (int n : {1, 2, 3}) {
        std::mutex m;
        std::multiset<int> seen;
        std::set<std::thread::id> ids;
        for (int round = 0; round < 50; ++round)
            runShares(n, [&](int t, int of) {
                std::lock_guard<std::mutex> lock(m);
                EXPECT_EQ(of, n);
                seen.insert(t);
                ids.insert(std::this_thread::get_id());
            });
        for (int t = 0; t < n; ++t) EXPECT_EQ(seen.count(t), 50u) << "share " << t << " of " << n;
        EXPECT_EQ(seen.size(), 50u * static_cast<size_t>(n));
        EXPECT_EQ(ids.size(), static_cast<size_t>(n)) << "share 0 on the caller, the others on helpers";
    }
}

TEST(Threads, RunSharesRethrowsAfterEveryShareEnded) {
    std::atomic<int> ended{0};
    EXPECT_THROW(runShares(2,
                           [&](int t, int) {
                               if (t == 1) {
                                   ended.fetch_add(1);
                                   throw std::runtime_error("share 1");
                               }
                               std::this_thread::sleep_for(std::chrono::milliseconds(20));
                               ended.fetch_add(1);
                           }),
                 std::runtime_error);
    EXPECT_EQ(ended.load(), 2);
    int calls = 0;  // and the team still works afterwards
    std::mutex m;
    runShares(2, [&](int, int) {
        std::lock_guard<std::mutex> lock(m);
        ++calls;
    });
    EXPECT_EQ(calls, 2);
}

TEST(Threads, ForEachShareCoversTheItemsInContiguousShares) {
    std::vector<int> hits(1000, 0);
    forEachShare(1000, 2, 256, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) ++hits[static_cast<size_t>(i)];
    });
    for (int h : hits) EXPECT_EQ(h, 1);
    int calls = 0;  // below minParallel: one call
    forEachShare(100, 2, 256, [&](int begin, int end) {
        ++calls;
        EXPECT_EQ(begin, 0);
        EXPECT_EQ(end, 100);
    });
    EXPECT_EQ(calls, 1);
}

TEST(Threads, TeamCapLimitsTheTeamAndNests) {
    EXPECT_EQ(teamThreads(2), 2);
    {
        TeamCap one(1);
        EXPECT_EQ(teamThreads(2), 1);
        {
            TeamCap three(3);  // nested: the smaller stays
            EXPECT_EQ(teamThreads(2), 1);
        }
    }
    EXPECT_EQ(teamThreads(2), 2);
    EXPECT_EQ(teamThreads(0), 1);
}

TEST(Threads, FixedTeamsKeepTheirSize) {
    for (int n : {1, 2, 3}) {
        AdaptiveTeam team(n);
        EXPECT_FALSE(team.adaptive());
        drive(team, 100, [](int size) { return size == 1 ? 0.001 : 1.0; });  // even when one thread is faster
        EXPECT_EQ(team.threads(), n);
        EXPECT_EQ(team.switches(), 0);
    }
    const DefaultThreads one(1);
    EXPECT_FALSE(AdaptiveTeam(0).adaptive()) << "one core: nothing to choose";
    EXPECT_EQ(AdaptiveTeam(0).threads(), 1);
}

TEST(Threads, AdaptiveTeamKeepsTheFasterSizeAndFollowsTheLoad) {
    const DefaultThreads two(2);
    AdaptiveTeam team(0);
    ASSERT_TRUE(team.adaptive());
    EXPECT_EQ(team.threads(), 2) << "starts with all cores";
    // Idle: two threads take half the time. After the start, one unit in kLongestInterval = 64 at most
    // on one thread.
    const auto idle = [](int size) { return size == 1 ? 2.0 : 1.0; };
    drive(team, 4000, idle);
    EXPECT_EQ(team.threads(), 2);
    EXPECT_LE(team.units(1), 4 + 4000 / AdaptiveTeam::kLongestInterval + 8) << "probes of one thread";
    EXPECT_GE(team.units(1), 4000 / AdaptiveTeam::kLongestInterval / 2) << "and it keeps probing";
    // Busy: two threads now take 3 times one thread's time; within one probe interval it follows.
    const auto busy = [](int size) { return size == 1 ? 2.0 : 6.0; };
    const long before = team.units(2);
    drive(team, 300, busy);
    EXPECT_EQ(team.threads(), 1);
    EXPECT_LE(team.units(2) - before, AdaptiveTeam::kLongestInterval + 2);
    // It stays on one thread, probing two threads rarely: about 1 unit in 64 after backing off.
    const long onTwo = team.units(2);
    drive(team, 4000, busy);
    EXPECT_EQ(team.threads(), 1);
    EXPECT_LE(team.units(2) - onTwo, 4000 / AdaptiveTeam::kLongestInterval + 4);
    // Idle again: back to two threads.
    drive(team, 300, idle);
    EXPECT_EQ(team.threads(), 2);
    EXPECT_GE(team.switches(), 2);
}

TEST(Threads, AdaptiveTeamProbesAtOnceWhenTheCurrentSizeGetsSlower) {
    const DefaultThreads two(2);
    AdaptiveTeam team(0);
    drive(team, 100, [](int size) { return size == 1 ? 2.0 : 1.0; });
    ASSERT_EQ(team.threads(), 2);
    // Two threads become slower than one thread was (T = 3 s against 2 s): T̄ = 1.5, 1.875, 2.16 s, so
    // the third such unit is followed by a probe on one thread, long before the probe interval ends.
    for (int k = 0; k < 2; ++k) {
        team.record(3.0);
        EXPECT_EQ(team.threads(), 2) << "T̄ still below one thread's after " << k + 1;
    }
    team.record(3.0);
    EXPECT_EQ(team.threads(), 1) << "a probe right after the average passes one thread's";
    team.record(2.0);  // the probe wins (2 s < 0.95 · 2.16 s)
    EXPECT_EQ(team.threads(), 1) << "a second probe";
    EXPECT_EQ(team.switches(), 0);
    team.record(2.0);  // wins too: one thread is current
    EXPECT_EQ(team.threads(), 1);
    EXPECT_EQ(team.switches(), 1);
}

// One lucky probe (the neighbour paused for one unit) does not switch the team: the probe after it
// loses, and the team stays, probing again only after the (doubled) interval.
TEST(Threads, AdaptiveTeamIgnoresOneLuckyProbe) {
    const DefaultThreads two(2);
    AdaptiveTeam team(0);
    drive(team, 300, [](int size) { return size == 1 ? 1.0 : 5.0; });  // busy: one thread is current
    ASSERT_EQ(team.threads(), 1);
    const long switches = team.switches();
    while (team.threads() == 1) team.record(1.0);
    team.record(0.5);  // the probe of two threads: lucky
    ASSERT_EQ(team.threads(), 2) << "a second probe";
    team.record(5.0);  // loses
    EXPECT_EQ(team.threads(), 1);
    EXPECT_EQ(team.switches(), switches);
    for (int k = 0; k < AdaptiveTeam::kLongestInterval - 1; ++k) {
        team.record(1.0);
        ASSERT_EQ(team.threads(), 1) << "no probe before the interval is over, unit " << k;
    }
}

TEST(Threads, AdaptiveTeamSwitchesOnlyForTheMargin) {
    const DefaultThreads two(2);
    AdaptiveTeam team(0);
    // One thread 3 % faster than two: within the margin (5 %), it stays on two threads.
    drive(team, 1000, [](int size) { return size == 1 ? 0.97 : 1.0; });
    EXPECT_EQ(team.threads(), 2);
    EXPECT_EQ(team.switches(), 0);
    // 10 % faster: it switches.
    drive(team, 200, [](int size) { return size == 1 ? 0.9 : 1.0; });
    EXPECT_EQ(team.threads(), 1);
}

// A probe stops once it cannot win (units timed on a made-up clock, setTeamClock(), so the machine's
// load cannot change which size the loops get): one thread is current, a loop takes 0.5 ms on one
// thread and 20 ms on two, so a whole probe of two threads would take 200 ms. Its first loops run on
// two threads until it has used (1 - kMargin) of one thread's time, then the rest on one thread; the
// team stays on one thread. When two threads get fast, a probe runs whole and wins.
namespace {
std::chrono::steady_clock::time_point madeUpNow{};  // the made-up clock's time
std::chrono::steady_clock::time_point madeUpClock() { return madeUpNow; }
struct MadeUpClock {
    MadeUpClock() { setTeamClock(madeUpClock); }
    ~MadeUpClock() { setTeamClock(nullptr); }
};
}  // namespace

TEST(Threads, AProbeStopsOnceItCannotWinAndRunsWholeWhenItWins) {
    const DefaultThreads two(2);
    const MadeUpClock clock;
    AdaptiveTeam team(0);
    drive(team, 200, [](int size) { return size == 1 ? 0.010 : 0.100; });  // made up: T̄ = 10 ms on one thread
    ASSERT_EQ(team.threads(), 1);
    const long switches = team.switches();
    // One unit of 10 loops, each advancing the made-up clock; returns how many of them got two threads.
    const auto unit = [&](double msOnOne, double msOnTwo) {
        const auto u = team.unit();
        int onTwo = 0;
        for (int k = 0; k < 10; ++k) {
            const bool both = teamThreads(2) == 2;
            onTwo += both;
            madeUpNow += std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                std::chrono::duration<double, std::milli>(both ? msOnTwo : msOnOne));
        }
        return onTwo;
    };
    int probes = 0;
    for (int k = 0; k < 3 * AdaptiveTeam::kLongestInterval && probes < 2; ++k) {
        const bool probe = team.threads() == 2;
        const int onTwo = unit(0.5, 20.0);
        if (!probe) {
            EXPECT_EQ(onTwo, 0) << "unit " << k << " on one thread";
            continue;
        }
        ++probes;
        EXPECT_GE(onTwo, 1) << "the probe starts on two threads";
        EXPECT_EQ(onTwo, 1) << "the probe went on after it could no longer win (a loop on two threads takes 20 ms, one thread's whole unit 5 ms)";
        EXPECT_EQ(team.threads(), 1) << "the probe lost";
    }
    EXPECT_EQ(probes, 2) << "probes come at least every kLongestInterval units";
    EXPECT_EQ(team.switches(), switches);
    // Two threads fast now (0.05 ms a loop): the next probe runs all 10 loops on two threads and wins.
    for (int k = 0; k < 3 * AdaptiveTeam::kLongestInterval && team.threads() == 1; ++k) unit(0.5, 0.05);
    ASSERT_EQ(team.threads(), 2) << "a probe of two threads";
    EXPECT_EQ(unit(0.5, 0.05), 10) << "a winning probe is not cut";
    EXPECT_EQ(team.switches(), switches) << "one winning probe does not switch";
    ASSERT_EQ(team.threads(), 2) << "a second probe follows";
    EXPECT_EQ(unit(0.5, 0.05), 10);
    EXPECT_EQ(team.switches(), switches + 1) << "two winning probes switch";
    EXPECT_EQ(team.threads(), 2);
}

// The default solver.threads = 0 with two cores: the team switches between one and two threads while
// the cloth runs (timed; whichever is faster here), and the state is the serial run's, bit for bit.
TEST(Threads, AdaptiveDefaultGivesTheSerialStateBitForBit) {
    const DefaultThreads two(2);
    for (const std::string method : {"pbd", "xpbd"}) {
        const std::vector<std::string> sets = {"cloth.nx=40", "cloth.ny=40", "solver.method=" + method};
        auto serial = sets, adaptive = sets;
        serial.push_back("solver.threads=1");
        adaptive.push_back("solver.threads=0");
        PbdSimulation one(scene("pbd_sphere", serial)), chosen(scene("pbd_sphere", adaptive));
        ASSERT_TRUE(chosen.team().adaptive());
        for (int k = 0; k < 60; ++k) one.step(), chosen.step();
        EXPECT_TRUE(bitIdentical(one.state().x, chosen.state().x)) << method;
        EXPECT_TRUE(bitIdentical(one.state().v, chosen.state().v)) << method;
        // Both sizes ran (the start measures both, a probe comes every 64 steps at most)
        EXPECT_GE(chosen.team().units(1), 2) << method;
        EXPECT_GE(chosen.team().units(2), 2) << method;
    }
}

// Switching the team size from one iteration to the next, in a fixed made-up pattern (TeamCap around
// some steps of a two-thread run): the serial state bit for bit after every switch.
TEST(Threads, SwitchingTheTeamSizeMidRunGivesTheSerialStateBitForBit) {
    const std::vector<std::string> sets = {"cloth.nx=40", "cloth.ny=40"};
    auto serial = sets, two = sets;
    serial.push_back("solver.threads=1");
    two.push_back("solver.threads=2");
    PbdSimulation one(scene("pbd_sphere", serial)), switching(scene("pbd_sphere", two));
    for (int k = 0; k < 60; ++k) {
        one.step();
        if (k % 3 == 1) {
            TeamCap serialStep(1);
            switching.step();
        } else {
            switching.step();
        }
        ASSERT_TRUE(bitIdentical(one.state().x, switching.state().x)) << "step " << k;
    }
    EXPECT_TRUE(bitIdentical(one.state().v, switching.state().v));
}

TEST(Threads, AdaptiveImplicitEulerGivesTheSerialStateBitForBit) {
    // parallel_test.cpp's 32 x 32 cloth on the block solver, 20 steps of 0.01 s.
    const DefaultThreads two(2);
    const std::string json = R"({"model": "cloth", "cloth": {"nx": 32, "ny": 32, "pins": ["top-edge"], "orientation": "horizontal"},
        "springs": {"structural": {"k": 100, "kd": 0.01}, "shear": {"k": 50}, "bending": {"k": 10}},
        "forces": {"air_damping": 0.001}, "solver": {"method": "implicit_euler", "dt": 0.01}})";
    Matrix3X x[2], v[2];
    for (int threads : {0, 1}) {
        auto sim = makeSimulation(parseScene(json, "implicit", {"solver.threads=" + std::to_string(threads)}));
        auto& solver = dynamic_cast<MassSpringSimulation&>(*sim).implicitSolver();
        solver.setSolve(ImplicitSolve::BlockCg);
        EXPECT_EQ(solver.team().adaptive(), threads == 0);
        for (int k = 0; k < 20; ++k) sim->step();
        if (threads == 0) {
            EXPECT_GE(solver.team().units(1), 2) << "the start measures one thread too";
        }
        x[threads] = sim->state().x, v[threads] = sim->state().v;
    }
    EXPECT_TRUE(bitIdentical(x[0], x[1]));
    EXPECT_TRUE(bitIdentical(v[0], v[1]));
}
