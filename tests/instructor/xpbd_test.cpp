// XPBD (framework/src/sim/xpbd.cpp) is built on the student's exercises 4.3 and 5.2. This checks it
// against the XPBD update written out from the gradients (Macklin et al. 2016):
// S = Σ w_i|∇_i C|², Δλ = (−C − α̃λ)/(S + α̃), Δp_i = w_i ∇_i C Δλ; for distance
// ∇_1 C = −∇_2 C = (p1 − p2)/|p1 − p2|, for bending ∇_i C = −q_i / sin φ (exercise 5.1).
// Instructor-only: the expectations spell out the stage-04 and stage-05 projections.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "clothlab/sim/xpbd.h"

using namespace clothlab;

TEST(XpbdBending, MatchesTheUpdateWrittenOutFromTheGradients) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0), mass(0.1, 3.0);
    int checked = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const Vec3 p1(0, 0, 0), p2(1, 0, 0);
        const Vec3 p3(u(rng), 1.0 + 0.5 * u(rng), 0.8 * u(rng)), p4(u(rng), -1.0 - 0.5 * u(rng), 0.8 * u(rng));
        const double w[4] = {trial % 7 == 0 ? 0.0 : mass(rng), mass(rng), mass(rng), mass(rng)};
        const double phi0 = M_PI - 0.6 * std::abs(u(rng));
        const double alphaTilde = std::pow(10.0, 3.0 * u(rng)) * (trial % 5 == 0 ? 0.0 : 1.0);
        const double lambda0 = trial % 3 == 0 ? 0.0 : 0.2 * u(rng);

        const BendingGradients g = bendingGradients(p1, p2, p3, p4);
        ASSERT_TRUE(g.valid);
        if (g.sinPhi < 1e-3) continue;
        const Vec3 grad[4] = {-g.q1 / g.sinPhi, -g.q2 / g.sinPhi, -g.q3 / g.sinPhi, -g.q4 / g.sinPhi};
        double S = 0.0;
        for (int i = 0; i < 4; ++i) S += w[i] * grad[i].squaredNorm();
        const double C = std::atan2(g.sinPhi, g.d) - phi0;
        const double dl = (-C - alphaTilde * lambda0) / (S + alphaTilde);

        double lambda = lambda0;
        const BendingCorrection r = projectBendingXpbd(p1, p2, p3, p4, w[0], w[1], w[2], w[3], phi0, alphaTilde, lambda);
        const Vec3 got[4] = {r.dp1, r.dp2, r.dp3, r.dp4};
        EXPECT_NEAR(lambda, lambda0 + dl, 1e-12 * (1.0 + std::abs(dl))) << "trial " << trial;
        for (int i = 0; i < 4; ++i)
            EXPECT_LT((got[i] - w[i] * dl * grad[i]).norm(), 1e-12 * (1.0 + (w[i] * dl * grad[i]).norm()))
                << "trial " << trial << ", particle " << i + 1;
        ++checked;
    }
    EXPECT_GT(checked, 1500);
}

TEST(XpbdBending, ZeroComplianceIsThePbdProjectionWithStiffnessOne) {
    const Vec3 p1(0, 0, 0), p2(1, 0, 0), p3(0.3, 1, 0.2), p4(0.4, -1, 0.5);
    double lambda = 0.0;
    const BendingCorrection x = projectBendingXpbd(p1, p2, p3, p4, 1, 2, 0.5, 1, 2.8, 0.0, lambda);
    const BendingCorrection p = projectBendingConstraint(p1, p2, p3, p4, 1, 2, 0.5, 1, 2.8, 1.0);
    EXPECT_LT((x.dp1 - p.dp1).norm() + (x.dp2 - p.dp2).norm() + (x.dp3 - p.dp3).norm() + (x.dp4 - p.dp4).norm(), 1e-14);
}

TEST(XpbdDistance, MatchesTheUpdateWrittenOutFromTheGradient) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0), mass(0.1, 3.0);
    for (int trial = 0; trial < 2000; ++trial) {
        const Vec3 p1(u(rng), u(rng), u(rng)), p2(u(rng), u(rng), u(rng));
        const double w1 = trial % 7 == 0 ? 0.0 : mass(rng), w2 = mass(rng);
        const double d = 1.0 + 0.5 * u(rng);
        const double alphaTilde = std::pow(10.0, 3.0 * u(rng)) * (trial % 5 == 0 ? 0.0 : 1.0);
        const double lambda0 = trial % 3 == 0 ? 0.0 : 0.2 * u(rng);
        const double len = std::sqrt((p1 - p2).dot(p1 - p2));
        const Vec3 n = (p1 - p2) / len;  // ∇_1 C
        const double dl = (-(len - d) - alphaTilde * lambda0) / (w1 + w2 + alphaTilde);

        double lambda = lambda0;
        const DistanceCorrection r = projectDistanceXpbd(p1, p2, w1, w2, d, alphaTilde, lambda);
        EXPECT_NEAR(lambda, lambda0 + dl, 1e-12 * (1.0 + std::abs(dl))) << "trial " << trial;
        EXPECT_LT((r.dp1 - w1 * dl * n).norm(), 1e-12 * (1.0 + std::abs(w1 * dl))) << "trial " << trial;
        EXPECT_LT((r.dp2 + w2 * dl * n).norm(), 1e-12 * (1.0 + std::abs(w2 * dl))) << "trial " << trial;
    }
}

TEST(XpbdDistance, NoCorrectionForCoincidentOrPinnedEnds) {
    double lambda = 0.3;
    const DistanceCorrection c = projectDistanceXpbd(Vec3(1, 2, 3), Vec3(1, 2, 3), 1.0, 1.0, 0.5, 1e-3, lambda);
    EXPECT_EQ(c.dp1.norm() + c.dp2.norm(), 0.0);
    const DistanceCorrection p = projectDistanceXpbd(Vec3(0, 0, 0), Vec3(2, 0, 0), 0.0, 0.0, 0.5, 1e-3, lambda);
    EXPECT_EQ(p.dp1.norm() + p.dp2.norm(), 0.0);
    EXPECT_EQ(lambda, 0.3) << "no correction, no change of the multiplier";
}
