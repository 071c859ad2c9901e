// The batched self-collision pair search (solutions/kernels, solver.kernel "batched") against every
// pair of particles compared directly, and against exercises 7.3 and 7.4 (the solver's default):
// clouds of many sizes (tables of 2 to 8192 buckets, so that the 27 cells around a particle often
// share buckets), negative and far-off coordinates, coincident particles, and the folding curtain.
// In tests/instructor/ because the kernel is the instructor's (not in the student copy).
#include <algorithm>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "clothlab/io/scene_json.h"
#include "clothlab/sim/kernel_registry.h"
#include "clothlab/sim/pbd.h"

#if __has_include("neighbour_pairs_batched.h")
#include "neighbour_pairs_batched.h"

using namespace clothlab;

namespace {
using Pairs = std::vector<std::pair<int, int>>;

// Every pair i < j closer than d, by comparing all N(N − 1)/2 of them.
Pairs allPairsCloserThan(const Matrix3X& p, double d) {
    Pairs out;
    for (int i = 0; i < p.cols(); ++i)
        for (int j = i + 1; j < p.cols(); ++j)
            if ((p.col(i) - p.col(j)).squaredNorm() < d * d) out.emplace_back(i, j);
    return out;
}

// The pairs sorted, each checked for i < j (a pair twice stays twice).
Pairs sorted(const std::vector<ParticlePair>& pairs) {
    Pairs out;
    for (const ParticlePair& q : pairs) {
        EXPECT_LT(q.i, q.j);
        out.emplace_back(q.i, q.j);
    }
    std::sort(out.begin(), out.end());
    return out;
}

// n points in a box of side `side` around `centre`, some of them put on top of others.
Matrix3X cloud(int n, double side, const Vec3& centre, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    Matrix3X p(3, n);
    for (int i = 0; i < n; ++i) p.col(i) = centre + side * Vec3(u(rng), u(rng), u(rng));
    for (int i = 3; i < n; i += 7) p.col(i) = p.col(i / 2);  // coincident particles
    return p;
}
}  // namespace

TEST(NeighbourPairsBatched, FindsEveryPairOnceAndNoOther) {
    const double d = 0.03;
    int cases = 0;
    for (int n : {1, 2, 3, 5, 17, 100, 1000, 1500, 4096})
        for (const double side : {0.05, 0.3, 3.0})
            for (const Vec3& centre : {Vec3(0, 0, 0), Vec3(-1.7, 2.3, -0.4), Vec3(1e5, -1e5, 3e5)}) {
                const Matrix3X p = cloud(n, side, centre, static_cast<unsigned>(n + 7 * cases));
                const Pairs expected = allPairsCloserThan(p, d);
                EXPECT_EQ(sorted(neighbourPairsBatched(p, d)), expected) << n << " points in a box of " << side << " m at " << centre.transpose();
                ++cases;
            }
    EXPECT_EQ(cases, 81);
}

TEST(NeighbourPairsBatched, TheSamePairsAsExercises73And74) {
    const NeighbourSearch exercise = makeNeighbourSearch("exercise"), batched = makeNeighbourSearch("batched");
    for (int n : {2, 64, 1024, 3000}) {
        const Matrix3X p = cloud(n, 0.4, Vec3(-0.1, 0.05, 0.2), static_cast<unsigned>(n));
        const Pairs expected = sorted(exercise(p, 0.025));
        EXPECT_FALSE(n > 64 && expected.empty());
        EXPECT_EQ(sorted(batched(p, 0.025)), expected) << n << " points";
    }
}

// The folding curtain (300 steps with the batched kernel): at every 20th step the search on its
// positions gives the exercises' pairs, while its layers are in contact.
TEST(NeighbourPairsBatched, TheFoldingCurtainsPairsAtEveryStage) {
    PbdSimulation sim(loadScene(std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/pbd_self_collision.json", {"solver.kernel=batched"}));
    const NeighbourSearch exercise = makeNeighbourSearch("exercise");
    size_t most = 0;
    for (int k = 0; k < 300; ++k) {
        sim.step();
        if (k % 20 != 19) continue;
        const Matrix3X& x = sim.state().x;
        const Pairs expected = sorted(exercise(x, 0.05));
        most = std::max(most, expected.size());
        ASSERT_EQ(sorted(neighbourPairsBatched(x, 0.05)), expected) << "step " << k + 1;
    }
    EXPECT_GT(most, 3000u) << "the curtain folds: many pairs within 2 h";
}
#endif
