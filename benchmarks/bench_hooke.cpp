// Stage 01 kernels: one Hooke force evaluation and one integrator step of a chain.
#include <benchmark/benchmark.h>

#include "clothlab/io/scene_json.h"
#include "clothlab/exercise/01_hooke.h"
#include "clothlab/sim/simulation.h"

using namespace clothlab;

static void BM_HookeForce(benchmark::State& st) {
    Vec3 p0(0.1, 0.2, 0.3), p1(1.0, -0.5, 0.25);
    for (auto _ : st) {
        benchmark::DoNotOptimize(p1);
        benchmark::DoNotOptimize(hookeForce(p0, p1, 100.0, 1.0));
    }
}
BENCHMARK(BM_HookeForce);

// One step of a 1000-particle chain with each integrator; reports time per particle.
static void BM_ChainStep(benchmark::State& st, const char* method) {
    const Scene scene = parseScene(R"({"model": "chain", "chain": {"particles": 1000, "k": 100}})", "bench",
                                   {std::string("solver.method=") + method, "solver.dt=1e-4"});
    auto sim = makeSimulation(scene);
    for (auto _ : st) sim->step();
    st.counters["per_particle"] = benchmark::Counter(1000.0 * static_cast<double>(st.iterations()), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK_CAPTURE(BM_ChainStep, explicit_euler, "explicit_euler");
BENCHMARK_CAPTURE(BM_ChainStep, symplectic_euler, "symplectic_euler");
BENCHMARK_CAPTURE(BM_ChainStep, velocity_verlet, "velocity_verlet");
BENCHMARK_CAPTURE(BM_ChainStep, rk4, "rk4");

BENCHMARK_MAIN();
