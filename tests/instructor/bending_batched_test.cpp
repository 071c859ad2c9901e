// The batched bending kernel (solutions/kernels, solver.kernel "batched") against the
// reference: the same sweep as projectBendingSweep() with the stage-05 reference code, on crumpled
// cloths and on every degenerate stencil, and its arctan polynomial against std::atan2.
// In tests/instructor/ because the long-double check below spells out the solution of stage 05.
#include <cstring>
#include <cmath>
#include <algorithm>
#include <cstdio>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "clothlab/core/grid.h"
#include "clothlab/core/input_error.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/sim/pbd.h"
#include "crumpled_cloth.h"

#if __has_include("bending_batched.h")
#include "bending_batched.h"

using namespace clothlab;

namespace {
using test::hangingScene;

// The stencils of an n x n cloth in the solver's order, its inverse masses (some pinned, masses
// spread over three orders of magnitude) and crumpled positions: every stencil has work to do.
struct CrumpledCloth {
    std::vector<BendingStencil> stencils;
    VectorX w;
    Matrix3X p;
    CrumpledCloth(int n, unsigned seed) {
        const PbdSimulation sim(hangingScene({"cloth.nx=" + std::to_string(n), "cloth.ny=" + std::to_string(n)}));
        stencils = sim.bendingStencilList();
        std::mt19937 rng(seed);
        w = sim.state().w;
        p = sim.state().x;
        test::crumple(w, p, 1.0 / (n - 1), rng);  // the edge length is 1/(n − 1) m
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        for (auto& s : stencils) s.phi0 += 0.3 * u(rng);
    }
};

// Both loops of the batched kernel (on a CPU without AVX-512 both are the staged one).
constexpr BendingLoop kLoops[] = {BendingLoop::Best, BendingLoop::Staged};

// One stencil's Δp by both kernels (p1..p4 = particles 0..3).
void expectSameCorrection(const char* what, const Matrix3X& p0, const VectorX& w, double phi0) {
    SCOPED_TRACE(what);
    const std::vector<BendingStencil> one = {{0, 1, 2, 3, phi0}};
    Matrix3X ref = p0;
    projectBendingSweep(one, w, 1.0, ref);
    const double moved = (ref - p0).cwiseAbs().maxCoeff();  // the reference's largest correction
    for (BendingLoop loop : kLoops) {
        Matrix3X fast = p0;
        projectBendingBlocks(bendingBlocks(one), w, 1.0, fast, loop);
        ASSERT_TRUE(fast.allFinite()) << "NaN or Inf (staged " << (loop == BendingLoop::Staged) << ")";
        // 1e-9 of the correction itself, plus rounding of the positions (where the reference makes no
        // correction, the kernel may differ only by rounding: e.g. at the rest angle, std::atan2 vs the
        // kernel's polynomial)
        EXPECT_LE((fast - ref).cwiseAbs().maxCoeff(), 1e-9 * moved + 1e-14 * p0.cwiseAbs().maxCoeff())
            << "staged " << (loop == BendingLoop::Staged) << ", batched:\n" << fast << "\nreference:\n" << ref;
    }
}
}  // namespace

TEST(BendingBatched, Atan2PolynomialMatchesStdAtan2) {
    double worst = 0.0;
    for (double r : {1e-30, 1e-8, 1.0, 1e12})
        for (int k = 0; k <= 200000; ++k) {
            const double theta = M_PI * k / 200000.0;
            const double y = std::abs(r * std::sin(theta)), x = r * std::cos(theta);
            worst = std::max(worst, std::abs(atan2Upper(y, x) - std::atan2(y, x)));
        }
    EXPECT_LE(worst, 1e-15) << "largest difference to std::atan2 over [0, π]";
    EXPECT_EQ(atan2Upper(0.0, 1.0), 0.0);
    EXPECT_NEAR(atan2Upper(0.0, -1.0), M_PI, 1e-15);
    EXPECT_NEAR(atan2Upper(1.0, 0.0), M_PI / 2, 1e-15);
    EXPECT_NEAR(atan2Upper(1.0, 1.0), M_PI / 4, 1e-15);
}

// The blocks of `stencils`: in their order, each of 1..kBendingBlockSize stencils sharing no particle.
// Returns how many blocks are full.
int checkBlocks(const std::vector<BendingStencil>& stencils) {
    const BendingBlocks b = bendingBlocks(stencils);
    EXPECT_EQ(b.i1.size(), stencils.size());
    for (size_t s = 0; s < std::min(b.i1.size(), stencils.size()); ++s) {
        EXPECT_EQ(b.i1[s], stencils[s].i1);
        EXPECT_EQ(b.i2[s], stencils[s].i2);
        EXPECT_EQ(b.i3[s], stencils[s].i3);
        EXPECT_EQ(b.i4[s], stencils[s].i4);
        EXPECT_EQ(b.phi0[s], stencils[s].phi0);
    }
    int full = 0;
    const int blocks = static_cast<int>(b.start.size()) - 1;
    EXPECT_EQ(b.start.front(), 0);
    EXPECT_EQ(b.start.back(), static_cast<int>(stencils.size()));
    for (int k = 0; k < blocks; ++k) {
        const int size = b.start[k + 1] - b.start[k];
        EXPECT_GE(size, 1);
        EXPECT_LE(size, kBendingBlockSize);
        full += size == kBendingBlockSize;
        std::set<int> seen;
        for (int s = b.start[k]; s < b.start[k + 1]; ++s)
            for (int i : {b.i1[s], b.i2[s], b.i3[s], b.i4[s]}) EXPECT_TRUE(seen.insert(i).second) << "block " << k;
    }
    return full;
}

TEST(BendingBatched, BlocksKeepTheOrderAndShareNoParticle) {
    CrumpledCloth c(64, 1);
    const int blocks = static_cast<int>(bendingBlocks(c.stencils).start.size()) - 1;
    EXPECT_GE(checkBlocks(c.stencils), 0.9 * blocks) << "in the solver's colour order nearly every block is full";
    // Any order: the mesh order of bendingStencils() (neighbours one after another) and a shuffled one.
    const PbdSimulation sim(hangingScene({"cloth.nx=12", "cloth.ny=12"}));
    std::vector<BendingStencil> meshOrder = bendingStencils(gridTriangles(12, 12), sim.state().x);
    ASSERT_FALSE(meshOrder.empty());
    checkBlocks(meshOrder);
    std::shuffle(c.stencils.begin(), c.stencils.end(), std::mt19937(5));
    checkBlocks(c.stencils);
    checkBlocks({});
}

TEST(BendingBatched, SweepMatchesTheReferenceSweepOnCrumpledCloths) {
    // One sweep from the same positions. Both compute sin φ directly (no sqrt(1 − d²)), so they agree
    // to rounding: 5e-14 m measured on a 1 m cloth whose sweep moves particles by centimetres (the
    // textbook sqrt(1 − d²) gave 8e-10 m here). Many sweeps on a cloth this crumpled amplify any
    // rounding difference, so the comparison over a whole run is the scene test below.
    for (unsigned seed : {1u, 2u, 3u}) {
        const CrumpledCloth c(24, seed);
        const BendingBlocks b = bendingBlocks(c.stencils);
        for (double k : {1.0, 0.3, 0.01})
            for (BendingLoop loop : kLoops) {
                Matrix3X ref = c.p, fast = c.p;
                projectBendingSweep(c.stencils, c.w, k, ref);
                projectBendingBlocks(b, c.w, k, fast, loop);
                ASSERT_TRUE(fast.allFinite());
                EXPECT_GT((ref - c.p).cwiseAbs().maxCoeff(), 1e-2 * k) << "the sweep must have moved the cloth";
                EXPECT_LE((fast - ref).cwiseAbs().maxCoeff(), 1e-11)
                    << "seed " << seed << ", k " << k << ", staged " << (loop == BendingLoop::Staged);
            }
    }
}

TEST(BendingBatched, CorrectionAgreesWithLongDoubleArithmetic) {
    // Random stencils around flat (φ0 near π, as in a cloth), projected once; the truth is the same
    // formula (header of bending_batched.h) evaluated in long double with atan2l.
    using V = Eigen::Matrix<long double, 3, 1>;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    double worst = 0.0, worstReference = 0.0;
    for (int t = 0; t < 20000; ++t) {
        Matrix3X p(3, 4);
        p << 0, 1, 0.5, 0.5, 0, 0, 1, -1, 0, 0, 0, 0;
        for (int i = 0; i < 4; ++i)
            for (int c = 0; c < 3; ++c) p(c, i) += 0.4 * u(rng);
        VectorX w(4);
        for (int i = 0; i < 4; ++i) w[i] = std::pow(10.0, 1.5 * u(rng));
        const double phi0 = M_PI + 0.5 * u(rng);
        const std::vector<BendingStencil> one = {{0, 1, 2, 3, phi0}};
        Matrix3X ref = p, fast = p, staged = p;
        projectBendingSweep(one, w, 1.0, ref);
        projectBendingBlocks(bendingBlocks(one), w, 1.0, fast);
        projectBendingBlocks(bendingBlocks(one), w, 1.0, staged, BendingLoop::Staged);

        const Eigen::Matrix<long double, 3, 4> P = p.cast<long double>();
        const V a = P.col(1) - P.col(0), b = P.col(2) - P.col(0), c = P.col(3) - P.col(0);
        const V m1 = a.cross(b), m2 = a.cross(c);
        const long double L1 = m1.squaredNorm(), L2 = m2.squaredNorm(), D = m1.dot(m2);
        const long double S = m1.cross(m2).norm();
        if (L1 < 1e-20L || L2 < 1e-20L || S * S < 1e-10L * L1 * L2) continue;  // away from the cut-offs
        const V E1 = L1 * m2 - D * m1, E2 = L2 * m1 - D * m2;
        V Q[4];
        Q[2] = L2 * E1.cross(a);
        Q[3] = L1 * E2.cross(a);
        Q[1] = L2 * b.cross(E1) + L1 * c.cross(E2);
        Q[0] = -Q[1] - Q[2] - Q[3];
        long double Dn = 0;
        for (int i = 0; i < 4; ++i) Dn += w[i] * Q[i].squaredNorm();
        const long double f = (std::atan2(S, D) - phi0) * L1 * L2 * S / Dn;
        for (int i = 0; i < 4; ++i) {
            const V truth = P.col(i) + f * w[i] * Q[i];
            worst = std::max(worst, static_cast<double>((truth - fast.col(i).cast<long double>()).cwiseAbs().maxCoeff()));
            worst = std::max(worst, static_cast<double>((truth - staged.col(i).cast<long double>()).cwiseAbs().maxCoeff()));
            worstReference =
                std::max(worstReference, static_cast<double>((truth - ref.col(i).cast<long double>()).cwiseAbs().maxCoeff()));
        }
    }
    EXPECT_LE(worst, 1e-11) << "largest error of the batched kernel, m (stencils of about 1 m)";
    EXPECT_LE(worstReference, 1e-11) << "largest error of the stage-05 reference, m (bending_accuracy_test.cpp)";
    std::printf("largest error against long double: batched kernel %.2g m, stage-05 reference %.2g m (%s)\n", worst,
                worstReference, bendingBlocksUseScatter() ? "AVX-512 and staged" : "staged");
}

TEST(BendingBatched, DegenerateStencilsGiveTheReferenceResultAndNoNaN) {
    Matrix3X p(3, 4);
    const VectorX w = VectorX::Ones(4);
    p << 0, 1, 0.5, 0.5, 0, 0, 1, -1, 0, 0, 0.2, 0.3;  // columns p1..p4: a bent stencil
    expectSameCorrection("bent", p, w, 2.0);
    const BendingGradients rest = bendingGradients(p.col(0), p.col(1), p.col(2), p.col(3));
    expectSameCorrection("bent, at its rest angle", p, w, std::atan2(rest.sinPhi, rest.d));
    for (double scale : {1e-5, 1e3}) expectSameCorrection("bent, scaled", scale * p, w, 2.0);
    Matrix3X flat = p;
    flat.row(2).setZero();
    expectSameCorrection("flat (φ = π)", flat, w, 2.0);
    Matrix3X nearlyFlat = flat;
    nearlyFlat(2, 3) = 1e-8;  // sin φ ≈ 1e-8: below the cut-off 1e-6, no correction
    expectSameCorrection("nearly flat", nearlyFlat, w, 2.0);
    Matrix3X folded = flat;
    folded(1, 3) = 1.0;  // p4 on the same side as p3: φ = 0
    expectSameCorrection("folded (φ = 0)", folded, w, 2.0);
    Matrix3X zeroArea = p;
    zeroArea.col(2) << 0.5, 0, 0;  // p3 on the edge p1-p2
    expectSameCorrection("zero-area triangle", zeroArea, w, 2.0);
    Matrix3X coincident = p;
    coincident.col(1) = coincident.col(0);
    expectSameCorrection("coincident edge points", coincident, w, 2.0);
    expectSameCorrection("all pinned", p, VectorX::Zero(4), 2.0);
    VectorX heavy = w;
    heavy[2] = 1e-6;  // mass ratio 1e6
    expectSameCorrection("mass ratio 1e6", p, heavy, 2.0);
    expectSameCorrection("everything at the origin", Matrix3X::Zero(3, 4), w, 2.0);
}

TEST(BendingBatched, SceneOptionRunsTheSameSimulation) {
    // Starting horizontal, the cloth drapes in 3D, so bending matters (hanging in its own plane, every
    // stencil would stay flat and no bending code would change anything).
    const std::string horizontal = "cloth.orientation=horizontal";
    auto ref = makeSimulation(hangingScene({horizontal}));
    auto fast = makeSimulation(hangingScene({horizontal, "solver.kernel=batched"}));
    auto none = makeSimulation(hangingScene({horizontal, "constraints.bending.enabled=false"}));
    for (int i = 0; i < 100; ++i) {
        ref->step();
        fast->step();
        none->step();
    }
    EXPECT_GT((none->state().x - ref->state().x).cwiseAbs().maxCoeff(), 1e-2) << "bending must matter here";
    EXPECT_LE((fast->state().x - ref->state().x).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(BendingBatched, XpbdSweepMatchesTheExerciseXpbdSweep) {
    // XPBD through the kernel: the same multipliers and positions as projectBendingSweepXpbd() (exercise
    // 5.2 per stencil), up to rounding, on crumpled cloths, for stiff (α̃ = 0) and compliant angles;
    // λ carries over between the sweeps of a step, so three sweeps.
    for (unsigned seed : {1u, 2u})
        for (double alphaTilde : {0.0, 1e-3, 10.0})
            for (BendingLoop loop : kLoops) {
                SCOPED_TRACE("seed " + std::to_string(seed) + ", alphaTilde " + std::to_string(alphaTilde) +
                             (loop == BendingLoop::Staged ? ", staged" : ""));
                const CrumpledCloth c(24, seed);
                const BendingBlocks b = bendingBlocks(c.stencils);
                Matrix3X ref = c.p, fast = c.p;
                std::vector<double> lambdaRef(c.stencils.size(), 0.0), lambdaFast(c.stencils.size(), 0.0);
                for (int sweep = 0; sweep < 3; ++sweep) {
                    projectBendingSweepXpbd(c.stencils, c.w, alphaTilde, lambdaRef, ref);
                    projectBendingBlocksXpbd(b, c.w, alphaTilde, lambdaFast, fast, loop);
                }
                ASSERT_TRUE(fast.allFinite());
                const double moved = (ref - c.p).cwiseAbs().maxCoeff();
                EXPECT_GT(moved, 1e-3) << "the sweeps must move the cloth";
                EXPECT_LE((fast - ref).cwiseAbs().maxCoeff(), 1e-10);
                const auto [lambdaMax, lambdaDiff] = test::largestAndDifference(lambdaRef, lambdaFast);
                EXPECT_GT(lambdaMax, 0.0);
                EXPECT_LE(lambdaDiff, 1e-9 * lambdaMax);
            }
}

TEST(BendingBatched, XpbdSceneOptionRunsTheSameSimulation) {
    const std::vector<std::string> xpbd = {"cloth.orientation=horizontal", "solver.method=xpbd",
                                           "constraints.bending.compliance=0.01"};
    std::vector<std::string> batched = xpbd;
    batched.push_back("solver.kernel=batched");
    auto ref = makeSimulation(hangingScene(xpbd));
    auto fast = makeSimulation(hangingScene(batched));
    for (int i = 0; i < 100; ++i) ref->step(), fast->step();
    EXPECT_LE((fast->state().x - ref->state().x).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(BendingBatched, TwoThreadsGiveTheSerialStateBitForBit) {
    // The blocks of one colour group run in parallel (solver.threads): the same state bit for bit.
    const std::vector<std::string> sets = {"cloth.orientation=horizontal", "cloth.nx=48", "cloth.ny=40",
                                           "solver.kernel=batched"};
    Matrix3X x[2];
    for (int threads : {1, 2}) {
        std::vector<std::string> s = sets;
        s.push_back("solver.threads=" + std::to_string(threads));
        auto sim = makeSimulation(hangingScene(s));
        for (int i = 0; i < 60; ++i) sim->step();
        x[threads - 1] = sim->state().x;
    }
    EXPECT_EQ(std::memcmp(x[0].data(), x[1].data(), sizeof(double) * static_cast<size_t>(x[0].size())), 0)
        << "max difference " << (x[0] - x[1]).cwiseAbs().maxCoeff();
}
#endif
