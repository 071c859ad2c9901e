// Stages 03-05 kernels: one distance projection, one bending projection, one full PBD step.
// Per-constraint times come from the solver's own sweeps (projectDistanceSweep(),
// projectBendingSweep() in sim/sweeps.h: load p_i, call the stage-04/05 projection, add the
// corrections) over all constraints of a 64 x 64 cloth built by PbdSimulation, in the solver's
// order, reported as the counter per_constraint.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <benchmark/benchmark.h>

#include "clothlab/exercise/04_distance.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/sim/pbd.h"
#if __has_include("bending_batched.h")  // solutions/kernels: the instructor copy only
#include "bending_batched.h"
#define CLOTHLAB_BENCH_BATCHED 1
#endif

using namespace clothlab;

namespace {
// An n x n cloth scene pinned at two corners with distance and bending constraints, 10 iterations.
// Vertical, it hangs in its own plane (every stencil stays flat); horizontal, it drapes in 3D.
Scene clothScene(int n, const std::string& kernel = "exercise", const std::string& orientation = "vertical") {
    const std::string json = R"({"model": "cloth", "cloth": {"nx": )" + std::to_string(n) + R"(, "ny": )" +
                             std::to_string(n) + R"(, "orientation": ")" + orientation + R"(", "pins": ["top-left", "top-right"]},
        "constraints": {"distance": {"stiffness": 1.0}, "bending": {"stiffness": 0.1}},
        "solver": {"method": "pbd", "dt": 0.01, "iterations": 10, "kernel": ")" + kernel + R"("}})";
    return parseScene(json, "bench", {});
}

// The solver's constraints (in its colour order) of a 64 x 64 cloth, and positions slightly
// crumpled so that every constraint has work to do.
struct Cloth {
    Matrix3X p;
    VectorX w;
    std::vector<DistanceLink> links;
    std::vector<BendingStencil> stencils;
    Cloth() {
        const PbdSimulation sim(clothScene(64));
        links = sim.distanceLinks();
        stencils = sim.bendingStencilList();
        for (auto& s : stencils) s.phi0 -= 0.1;  // every stencil slightly away from its rest angle
        w = sim.state().w;
        p = sim.state().x;
        for (int i = 0; i < p.cols(); ++i) p(2, i) += 0.01 * std::sin(0.7 * i) * std::cos(0.3 * i);
    }
};

benchmark::Counter perConstraint(size_t n, benchmark::IterationCount iterations) {
    return benchmark::Counter(static_cast<double>(n) * static_cast<double>(iterations),
                              benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
}  // namespace

static void BM_DistanceProjection(benchmark::State& st) {
    Cloth c;
    for (auto _ : st) {
        projectDistanceSweep(c.links, c.w, 0.5, c.p);
        benchmark::ClobberMemory();
    }
    st.counters["per_constraint"] = perConstraint(c.links.size(), st.iterations());
}
BENCHMARK(BM_DistanceProjection);

// The same sweep in index order (edges sorted by particle index): consecutive projections share a
// particle and must wait for each other. Shows what colourOrder() buys.
static void BM_DistanceProjectionIndexOrder(benchmark::State& st) {
    Cloth c;
    std::sort(c.links.begin(), c.links.end(),
              [](const DistanceLink& a, const DistanceLink& b) { return std::make_pair(a.i, a.j) < std::make_pair(b.i, b.j); });
    for (auto _ : st) {
        projectDistanceSweep(c.links, c.w, 0.5, c.p);
        benchmark::ClobberMemory();
    }
    st.counters["per_constraint"] = perConstraint(c.links.size(), st.iterations());
}
BENCHMARK(BM_DistanceProjectionIndexOrder);

// Labelled as what it is: one constraint projected again and again on inputs that never change (a
// hot loop with no loads from the cloth, no dependency between calls). Not what the solver does;
// for comparison with figures measured that way.
static void BM_DistanceProjectionFixedInput(benchmark::State& st) {
    Vec3 p1(0.0, 0.0, 0.0), p2(0.011, 0.002, 0.001);
    for (auto _ : st) {
        benchmark::DoNotOptimize(p1);  // the compiler must not hoist the projection out of the loop
        benchmark::DoNotOptimize(p2);
        auto d = projectDistanceConstraint(p1, p2, 1.0, 1.0, 0.01, 0.5);
        benchmark::DoNotOptimize(d);
    }
}
BENCHMARK(BM_DistanceProjectionFixedInput);

static void BM_BendingProjection(benchmark::State& st) {
    Cloth c;
    for (auto _ : st) {
        projectBendingSweep(c.stencils, c.w, 0.01, c.p);
        benchmark::ClobberMemory();
    }
    st.counters["per_constraint"] = perConstraint(c.stencils.size(), st.iterations());
}
BENCHMARK(BM_BendingProjection);

#ifdef CLOTHLAB_BENCH_BATCHED
// The same sweep (same cloth, same stencils, same order) with the batched kernel of
// solutions/kernels (solver.kernel "batched"): 8 stencils at a time in AVX-512 registers.
// BendingLoop::Staged: the kernel's loop for CPUs without AVX-512 (no scatter instructions), forced.
static void bendingBatched(benchmark::State& st, BendingLoop loop) {
    Cloth c;
    const BendingBlocks blocks = bendingBlocks(c.stencils);
    for (auto _ : st) {
        projectBendingBlocks(blocks, c.w, 0.01, c.p, loop);
        benchmark::ClobberMemory();
    }
    st.counters["per_constraint"] = perConstraint(c.stencils.size(), st.iterations());
}
static void BM_BendingProjectionBatched(benchmark::State& st) { bendingBatched(st, BendingLoop::Best); }
BENCHMARK(BM_BendingProjectionBatched);
// On a CPU without AVX-512 this is what BM_BendingProjectionBatched measures.
static void BM_BendingProjectionBatchedStaged(benchmark::State& st) { bendingBatched(st, BendingLoop::Staged); }
BENCHMARK(BM_BendingProjectionBatchedStaged);
#endif

// One full step (gravity, distance + bending, 10 iterations) of an n x n cloth pinned at two
// corners, held horizontally at the start. Timed after one second (100 steps) of draping, when the
// stencils are bent: a flat cloth would be cheaper, since flat stencils take the early exit.
// Arguments: n, threads (solver.threads). Wall-clock time (the threads' work is not the main
// thread's CPU time).
static void step(benchmark::State& st, const std::string& kernel, const std::string& method) {
    const int n = static_cast<int>(st.range(0));
    Scene scene = clothScene(n, kernel, "horizontal");
    scene.solver.method = method == "xpbd" ? Method::Xpbd : Method::Pbd;
    scene.solver.threads = static_cast<int>(st.range(1));
    auto sim = makeSimulation(scene);
    for (int k = 0; k < 100; ++k) sim->step();  // warm-up: the cloth drapes
    for (auto _ : st) sim->step();
    st.counters["per_particle"] = benchmark::Counter(static_cast<double>(n) * n * st.iterations(),
                                                        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
// n = 32, 64, 128 on one thread; 64 and 128 on two; 128 with the default threads:0 (one thread or
// two, whichever the solver measures to be faster: sim/team.h; benchmarks/threads_under_load.sh).
static void stepArgs(benchmark::internal::Benchmark* b) {
    b->ArgNames({"n", "threads"})->Args({32, 1})->Args({64, 1})->Args({128, 1})->Args({64, 2})->Args({128, 2});
    b->Args({128, 0});
    b->Unit(benchmark::kMillisecond)->UseRealTime();
}
static void BM_PbdStep(benchmark::State& st) { step(st, "exercise", "pbd"); }
BENCHMARK(BM_PbdStep)->Apply(stepArgs);
// XPBD with the same iterations and substeps (its bending calls exercise 5.2 too).
static void BM_XpbdStep(benchmark::State& st) { step(st, "exercise", "xpbd"); }
BENCHMARK(BM_XpbdStep)->Apply(stepArgs);
#ifdef CLOTHLAB_BENCH_BATCHED
static void BM_PbdStepBatched(benchmark::State& st) { step(st, "batched", "pbd"); }
BENCHMARK(BM_PbdStepBatched)->Apply(stepArgs);
static void BM_XpbdStepBatched(benchmark::State& st) { step(st, "batched", "xpbd"); }
BENCHMARK(BM_XpbdStepBatched)->Apply(stepArgs);
#endif

BENCHMARK_MAIN();
