// Stage 02 kernels on square cloths of 32², 64² and 128² particles: the spring-force accumulation
// (addClothSpringForces) and one full step of each integrator. Counters: time per spring and per particle.
#include <benchmark/benchmark.h>

#include "clothlab/exercise/02_mfn.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/sim/mass_spring.h"

using namespace clothlab;

namespace {
// A cloth hanging from its top edge with structural, shear and bending springs. Soft enough that every
// explicit method is stable at dt = 1e-4 s.
Scene clothScene(int n, const std::string& method) {
    const std::string json = R"({"model": "cloth", "cloth": {"nx": )" + std::to_string(n) + R"(, "ny": )" + std::to_string(n) +
                             R"(, "pins": ["top-edge"]}, "springs": {"structural": {"k": 100, "kd": 0.01}, "shear": {"k": 50},
                             "bending": {"k": 10}}, "forces": {"air_damping": 0.001}})";
    return parseScene(json, "bench", {"solver.method=" + method, "solver.dt=1e-4"});
}

void perItem(benchmark::State& st, double springs, double particles) {
    const double it = static_cast<double>(st.iterations());
    st.counters["per_spring"] = benchmark::Counter(it * springs, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    st.counters["per_particle"] = benchmark::Counter(it * particles, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    st.counters["springs"] = springs;
}
}  // namespace

// Spring forces of the whole cloth into f (Task 2.2), positions slightly disturbed.
static void BM_ClothSpringForces(benchmark::State& st) {
    const int n = static_cast<int>(st.range(0));
    const MassSpringModel m = makeCloth(clothScene(n, "symplectic_euler"));
    const Matrix3X x = m.state.x + 0.01 * Matrix3X::Random(3, m.state.size());
    const Matrix3X v = Matrix3X::Random(3, m.state.size());
    Matrix3X f = Matrix3X::Zero(3, m.state.size());
    for (auto _ : st) {
        f.setZero();
        addClothSpringForces(m.springs, x, v, f);
        benchmark::DoNotOptimize(f.data());
        benchmark::ClobberMemory();
    }
    perItem(st, static_cast<double>(m.springs.size()), n * n);
}
BENCHMARK(BM_ClothSpringForces)->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMicrosecond);

// One step of the whole simulation (forces + integrator) per method.
static void BM_ClothStep(benchmark::State& st, const char* method) {
    const int n = static_cast<int>(st.range(0));
    auto sim = makeSimulation(clothScene(n, method));
    const double springs = static_cast<double>(sim->edges().size());
    sim->step();  // set-up outside the timing (implicit Euler builds its sparsity pattern here)
    for (auto _ : st) sim->step();
    perItem(st, springs, n * n);
}
BENCHMARK_CAPTURE(BM_ClothStep, explicit_euler, "explicit_euler")->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ClothStep, symplectic_euler, "symplectic_euler")->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ClothStep, velocity_verlet, "velocity_verlet")->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ClothStep, rk4, "rk4")->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ClothStep, implicit_euler, "implicit_euler")->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond);

// Implicit Euler at the step it exists for: Δt = 0.01 s (100 times the explicit methods' step above),
// after 20 steps of swinging (warm-up), n = 64, 128, with each linear solver; every variant times the
// same 10 steps (21-30), so that solvers and thread counts meet the same states. Counters: the relative
// residual |b − A Δv|/|b| of the last solve and the solver's iterations (0 for a direct solve).
static void BM_ImplicitLargeStep(benchmark::State& st, ImplicitSolve how, int threads = 1) {
    const int n = static_cast<int>(st.range(0));
    Scene scene = clothScene(n, "implicit_euler");
    scene.solver.dt = 0.01;
    scene.solver.threads = threads;
    auto sim = makeSimulation(scene);
    dynamic_cast<MassSpringSimulation&>(*sim).implicitSolver().setSolve(how);
    for (int k = 0; k < 20; ++k) sim->step();
    for (auto _ : st) sim->step();
    for (const Metric& m : sim->metrics())
        if (m.name == "solve_residual" || m.name == "solve_iterations") st.counters[m.name] = m.value;
}
// The default (block CG above 300 unknowns) on 1 and 2 threads, and the sparse Cholesky factorisation.
BENCHMARK_CAPTURE(BM_ImplicitLargeStep, default, ImplicitSolve::Auto)->Arg(64)->Arg(128)->Iterations(10)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_ImplicitLargeStep, default_2_threads, ImplicitSolve::Auto, 2)->Arg(64)->Arg(128)->Iterations(10)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_ImplicitLargeStep, cholesky, ImplicitSolve::Cholesky)->Arg(64)->Arg(128)->Iterations(10)->Unit(benchmark::kMillisecond)->UseRealTime();

// The lecture scene scenes/mfn_implicit.json (k = 5000 N/m, Δt = 0.01 s) at n x n particles, each
// linear solver, steps 21-30: where ImplicitSolve::Auto switches from the exact solve to block CG
// (above 300 unknowns, sim/implicit_euler.cpp).
static void BM_ImplicitLectureCloth(benchmark::State& st, ImplicitSolve how) {
    const std::string n = std::to_string(st.range(0));
    auto sim = makeSimulation(loadScene(CLOTHLAB_SCENES_DIR "/mfn_implicit.json", {"cloth.nx=" + n, "cloth.ny=" + n, "solver.threads=1"}));
    dynamic_cast<MassSpringSimulation&>(*sim).implicitSolver().setSolve(how);
    for (int k = 0; k < 20; ++k) sim->step();
    for (auto _ : st) sim->step();
}
BENCHMARK_CAPTURE(BM_ImplicitLectureCloth, cholesky, ImplicitSolve::Cholesky)->Arg(10)->Arg(14)->Arg(20)->Iterations(10)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_ImplicitLectureCloth, block_cg, ImplicitSolve::BlockCg)->Arg(10)->Arg(14)->Arg(20)->Iterations(10)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
