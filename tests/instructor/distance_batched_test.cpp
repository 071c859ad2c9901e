// The batched distance kernel (solutions/kernels, solver.kernel "batched") against the solver's
// sweeps with the stage-04 reference: projectDistanceSweep() and projectDistanceSweepXpbd() on
// stretched and crumpled cloths, with pinned particles, coincident points and both ends pinned.
// In tests/instructor/ because the kernel is the instructor's (not in the student copy).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include "clothlab/io/scene_json.h"
#include "clothlab/sim/pbd.h"
#include "crumpled_cloth.h"

#if __has_include("distance_batched.h")
#include "distance_batched.h"

using namespace clothlab;

namespace {
using test::hangingScene;

// The links of an n x n cloth in the solver's colour order with its plan (2 threads), masses spread
// over three orders of magnitude (the solver's pins stay pinned) and positions moved by up to 30 % of
// an edge: every link has work to do. Then the cases without a correction: particle 1 on top of
// particle 0 (a link between them), and a link whose ends are both pinned.
struct CrumpledLinks {
    std::vector<DistanceLink> links;
    SweepPlan plan;
    VectorX w;
    Matrix3X p;
    CrumpledLinks(int n, unsigned seed) {
        const PbdSimulation sim(hangingScene({"cloth.nx=" + std::to_string(n), "cloth.ny=" + std::to_string(n),
                                              "solver.threads=2"}));
        links = sim.distanceLinks();
        plan = sim.distancePlan();
        std::mt19937 rng(seed);
        w = sim.state().w;
        p = sim.state().x;
        test::crumple(w, p, 1.0 / (n - 1), rng);  // the edge length is 1/(n − 1) m
        p.col(1) = p.col(0);
        w[links.back().i] = w[links.back().j] = 0.0;  // both ends pinned
    }
};
}  // namespace

TEST(DistanceBatched, SweepMatchesTheReferenceSweep) {
    for (unsigned seed : {1u, 2u, 3u}) {
        const CrumpledLinks c(24, seed);
        bool coincident = false, bothPinned = false;
        for (const DistanceLink& L : c.links) {
            coincident = coincident || (L.i + L.j == 1);
            bothPinned = bothPinned || (c.w[L.i] == 0.0 && c.w[L.j] == 0.0);
        }
        ASSERT_TRUE(coincident) << "a link between the coincident particles 0 and 1";
        ASSERT_TRUE(bothPinned);
        for (const SweepPlan& plan : {c.plan, SweepPlan{}})
            for (double k : {1.0, 0.3, 0.01}) {
                Matrix3X ref = c.p, fast = c.p;
                projectDistanceSweep(c.links, c.w, k, ref, plan);
                projectDistanceArrays(distanceArrays(c.links, plan), c.w, k, fast);
                ASSERT_TRUE(fast.allFinite());
                EXPECT_GT((ref - c.p).cwiseAbs().maxCoeff(), 1e-3 * k) << "the sweep must move the cloth";
                EXPECT_LE((fast - ref).cwiseAbs().maxCoeff(), 1e-14)
                    << "seed " << seed << ", k " << k << (plan.groups.empty() ? ", list order" : ", colour groups");
            }
    }
}

TEST(DistanceBatched, XpbdSweepMatchesTheExerciseXpbdSweep) {
    // λ carries over between the sweeps of a step: three sweeps, stiff and compliant.
    for (double alphaTilde : {0.0, 1e-3, 10.0}) {
        SCOPED_TRACE("alphaTilde " + std::to_string(alphaTilde));
        const CrumpledLinks c(24, 4);
        const DistanceArrays a = distanceArrays(c.links, c.plan);
        Matrix3X ref = c.p, fast = c.p;
        std::vector<double> lambdaRef(c.links.size(), 0.0), lambdaFast(c.links.size(), 0.0);
        for (int sweep = 0; sweep < 3; ++sweep) {
            projectDistanceSweepXpbd(c.links, c.w, alphaTilde, lambdaRef, ref, c.plan);
            projectDistanceArraysXpbd(a, c.w, alphaTilde, lambdaFast, fast);
        }
        ASSERT_TRUE(fast.allFinite());
        EXPECT_GT((ref - c.p).cwiseAbs().maxCoeff(), 1e-3) << "the sweeps must move the cloth";
        EXPECT_LE((fast - ref).cwiseAbs().maxCoeff(), 1e-13);
        const auto [lambdaMax, lambdaDiff] = test::largestAndDifference(lambdaRef, lambdaFast);
        EXPECT_GT(lambdaMax, 0.0);
        EXPECT_LE(lambdaDiff, 1e-12 * lambdaMax);
    }
}

TEST(DistanceBatched, TwoThreadsGiveTheSerialSweepBitForBit) {
    // Each thread sweeps one contiguous share of a colour group; where a share starts must not matter.
    const CrumpledLinks c(64, 5);
    SweepPlan serial = c.plan;
    serial.threads = 1;
    ASSERT_EQ(c.plan.threads, 2);
    Matrix3X x[2] = {c.p, c.p};
    std::vector<double> lambda[2] = {std::vector<double>(c.links.size(), 0.0), std::vector<double>(c.links.size(), 0.0)};
    const DistanceArrays one = distanceArrays(c.links, serial), two = distanceArrays(c.links, c.plan);
    for (int sweep = 0; sweep < 3; ++sweep) {
        projectDistanceArrays(one, c.w, 0.7, x[0]);
        projectDistanceArrays(two, c.w, 0.7, x[1]);
        projectDistanceArraysXpbd(one, c.w, 1e-3, lambda[0], x[0]);
        projectDistanceArraysXpbd(two, c.w, 1e-3, lambda[1], x[1]);
    }
    EXPECT_EQ(std::memcmp(x[0].data(), x[1].data(), sizeof(double) * static_cast<size_t>(x[0].size())), 0)
        << "max difference " << (x[0] - x[1]).cwiseAbs().maxCoeff();
    EXPECT_EQ(lambda[0], lambda[1]);
}
#endif
