// Stages 03-05 kernels: one distance projection, one bending projection, one full PBD step.
// Per-constraint times come from sweeps over all constraints of a 64 x 64 cloth (as in the solver:
// load p_i, project, add the corrections), reported as the counter per_constraint.
#include <algorithm>
#include <utility>

#include <benchmark/benchmark.h>

#include "clothlab/core/grid.h"
#include "clothlab/core/topology.h"
#include "clothlab/exercise/04_distance.h"
#include "clothlab/exercise/05_bending.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/sim/simulation.h"

using namespace clothlab;

namespace {
// A 64 x 64 cloth, slightly crumpled so that every constraint has work to do.
struct Cloth {
    Matrix3X x, p;
    VectorX w;
    std::vector<Eigen::Vector2i> edges;
    std::vector<double> rest;
    std::vector<BendingStencil> stencils;
    explicit Cloth(int n) {
        ClothSpec spec;
        spec.nx = spec.ny = n;
        const State s = makeGridState(spec);
        x = s.x;
        w = s.w;
        const auto tris = gridTriangles(n, n);
        // The solver's order: colourOrder() (consecutive constraints share no particle).
        const auto all = uniqueEdges(tris);
        std::vector<Eigen::Vector4i> sets;
        for (const auto& e : all) sets.emplace_back(e[0], e[1], -1, -1);
        for (int k : colourOrder(sets, n * n)) edges.push_back(all[static_cast<size_t>(k)]);
        for (const auto& e : edges) rest.push_back((x.col(e[0]) - x.col(e[1])).norm());
        const auto st = bendingStencils(tris, x);
        sets.clear();
        for (const auto& b : st) sets.emplace_back(b.i1, b.i2, b.i3, b.i4);
        for (int k : colourOrder(sets, n * n)) stencils.push_back(st[static_cast<size_t>(k)]);
        p = x;
        for (int i = 0; i < p.cols(); ++i) p(2, i) += 0.01 * std::sin(0.7 * i) * std::cos(0.3 * i);
    }
};
}  // namespace

static void BM_DistanceProjection(benchmark::State& st) {
    Cloth c(64);
    const size_t n = c.edges.size();
    for (auto _ : st) {
        for (size_t k = 0; k < n; ++k) {
            const int i = c.edges[k][0], j = c.edges[k][1];
            const auto d = projectDistanceConstraint(c.p.col(i), c.p.col(j), c.w[i], c.w[j], c.rest[k], 0.5);
            c.p.col(i) += d.dp1;
            c.p.col(j) += d.dp2;
        }
        benchmark::ClobberMemory();
    }
    st.counters["per_constraint"] =
        benchmark::Counter(static_cast<double>(n) * st.iterations(), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_DistanceProjection);

// The same sweep in index order (edges sorted by particle index): consecutive projections share a
// particle and must wait for each other. Shows what colourOrder() buys.
static void BM_DistanceProjectionIndexOrder(benchmark::State& st) {
    Cloth c(64);
    std::vector<size_t> order(c.edges.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return std::make_pair(c.edges[a][0], c.edges[a][1]) < std::make_pair(c.edges[b][0], c.edges[b][1]);
    });
    for (auto _ : st) {
        for (size_t k : order) {
            const int i = c.edges[k][0], j = c.edges[k][1];
            const auto d = projectDistanceConstraint(c.p.col(i), c.p.col(j), c.w[i], c.w[j], c.rest[k], 0.5);
            c.p.col(i) += d.dp1;
            c.p.col(j) += d.dp2;
        }
        benchmark::ClobberMemory();
    }
    st.counters["per_constraint"] = benchmark::Counter(static_cast<double>(order.size()) * st.iterations(),
                                                       benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_DistanceProjectionIndexOrder);

static void BM_BendingProjection(benchmark::State& st) {
    Cloth c(64);
    const size_t n = c.stencils.size();
    for (auto& s : c.stencils) s.phi0 -= 0.1;  // every stencil slightly away from its rest angle
    for (auto _ : st) {
        for (size_t k = 0; k < n; ++k) {
            const BendingStencil& s = c.stencils[k];
            const auto d = projectBendingConstraint(c.p.col(s.i1), c.p.col(s.i2), c.p.col(s.i3), c.p.col(s.i4), c.w[s.i1],
                                                    c.w[s.i2], c.w[s.i3], c.w[s.i4], s.phi0, 0.01);
            c.p.col(s.i1) += d.dp1;
            c.p.col(s.i2) += d.dp2;
            c.p.col(s.i3) += d.dp3;
            c.p.col(s.i4) += d.dp4;
        }
        benchmark::ClobberMemory();
    }
    st.counters["per_constraint"] =
        benchmark::Counter(static_cast<double>(n) * st.iterations(), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_BendingProjection);

// One full PBD step (gravity, distance + bending, 10 iterations) of an n x n cloth pinned at two corners.
static void BM_PbdStep(benchmark::State& st) {
    const int n = static_cast<int>(st.range(0));
    const std::string json = R"({"model": "cloth", "cloth": {"nx": )" + std::to_string(n) + R"(, "ny": )" +
                             std::to_string(n) + R"(, "pins": ["top-left", "top-right"]},
        "constraints": {"distance": {"stiffness": 1.0}, "bending": {"stiffness": 0.1}},
        "solver": {"method": "pbd", "dt": 0.01, "iterations": 10}})";
    auto sim = makeSimulation(parseScene(json, "bench", {}));
    for (auto _ : st) sim->step();
    st.counters["per_particle"] = benchmark::Counter(static_cast<double>(n) * n * st.iterations(),
                                                        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_PbdStep)->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
