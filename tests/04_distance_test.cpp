// Graded tests of stage 04 — the distance constraint.
// Test names start with the task they check (Task4_3 = exercise 4.3). Points: 04_distance.points.json.
// Expected values come from the formulas written here (|p1 - p2| - d, finite differences), not from your code.
#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "clothlab/exercise/04_distance.h"
#include "test_util.h"

using namespace clothlab;

namespace {

using testing_util::str;

// The cost function written independently: C = |p1 - p2| - d.
double C(const Vec3& p1, const Vec3& p2, double d) { return std::sqrt((p1 - p2).dot(p1 - p2)) - d; }

const Vec3 kP1(0.3, -0.2, 0.5), kP2(1.1, 0.4, -0.1);  // |p1 - p2| = sqrt(0.64+0.36+0.36) = 1.16619

}  // namespace

// ---- Task 4.1 --------------------------------------------------------------------------
TEST(Task4_1_DistanceConstraint, IsLengthMinusRestLength) {
    EXPECT_NEAR(distanceConstraint(kP1, kP2, 1.0), std::sqrt(1.36) - 1.0, 1e-12)
        << "C(p1, p2) must be |p1 - p2| - d (positive when stretched)";
    EXPECT_NEAR(distanceConstraint(kP1, kP2, 2.0), std::sqrt(1.36) - 2.0, 1e-12)
        << "C must be negative when the constraint is compressed (|p1 - p2| < d)";
    EXPECT_NEAR(distanceConstraint(kP2, kP1, 1.0), std::sqrt(1.36) - 1.0, 1e-12) << "C is symmetric in p1, p2";
}

// ---- Task 4.2 --------------------------------------------------------------------------
TEST(Task4_2_DistanceGradient, AgreesWithFiniteDifferencesOfC) {
    const double h = 1e-6, d = 0.7;
    const Vec3 g = distanceGradient(kP1, kP2);
    for (int a = 0; a < 3; ++a) {
        Vec3 e = Vec3::Zero();
        e[a] = h;
        const double fd1 = (C(kP1 + e, kP2, d) - C(kP1 - e, kP2, d)) / (2 * h);
        const double fd2 = (C(kP1, kP2 + e, d) - C(kP1, kP2 - e, d)) / (2 * h);
        EXPECT_NEAR(g[a], fd1, 1e-7) << "component " << a << " of grad_p1 C: yours " << str(g)
                                     << ", finite differences say " << fd1;
        EXPECT_NEAR(-g[a], fd2, 1e-7) << "grad_p2 C = -grad_p1 C must match finite differences (component " << a << ")";
    }
    EXPECT_NEAR(g.norm(), 1.0, 1e-12) << "the gradient of a distance is a unit vector";
}

TEST(Task4_2_DistanceGradient, CoincidentPointsGiveZeroNotNaN) {
    const Vec3 g = distanceGradient(kP1, kP1);
    EXPECT_TRUE(g.allFinite()) << "gradient of coincident points is " << str(g) << " (NaN/Inf)";
    EXPECT_EQ(g.norm(), 0.0) << "coincident points: the direction is undefined, return the zero vector";
}

// ---- Task 4.3 --------------------------------------------------------------------------
TEST(Task4_3_ProjectDistance, StiffnessOneSatisfiesTheConstraintExactly) {
    for (double d : {0.2, 1.0, 1.16619, 3.0}) {
        const auto c = projectDistanceConstraint(kP1, kP2, 2.0, 0.5, d, 1.0);
        EXPECT_NEAR(C(kP1 + c.dp1, kP2 + c.dp2, d), 0.0, 1e-12)
            << "after one projection with k = 1, |p1 - p2| must equal d = " << d;
    }
}

TEST(Task4_3_ProjectDistance, MovesAlongTheConstraintDirection) {
    const auto c = projectDistanceConstraint(kP1, kP2, 1.0, 1.0, 0.5, 1.0);
    const Vec3 n = (kP1 - kP2).normalized();
    EXPECT_LT((c.dp1 - c.dp1.dot(n) * n).norm(), 1e-12) << "dp1 = " << str(c.dp1) << " must be parallel to p1 - p2";
    EXPECT_LT(c.dp1.dot(n), 0.0) << "a stretched constraint pulls p1 towards p2";
    EXPECT_GT(c.dp2.dot(n), 0.0) << "a stretched constraint pulls p2 towards p1";
}

TEST(Task4_3_ProjectDistance, ConservesMomentum) {
    const double w1 = 4.0, w2 = 0.25;  // m1 = 0.25 kg, m2 = 4 kg
    const auto c = projectDistanceConstraint(kP1, kP2, w1, w2, 0.4, 0.7);
    const Vec3 momentum = c.dp1 / w1 + c.dp2 / w2;
    EXPECT_LT(momentum.norm(), 1e-12) << "sum m_i dp_i = " << str(momentum)
                                      << " must be zero: weight the corrections with w_i / (w1 + w2)";
    EXPECT_NEAR(c.dp1.norm() / c.dp2.norm(), w1 / w2, 1e-9) << "|dp1| / |dp2| must be w1 / w2 (light particles move more)";
}

TEST(Task4_3_ProjectDistance, StiffnessScalesTheCorrection) {
    const double d = 0.5, k = 0.3;
    const auto c = projectDistanceConstraint(kP1, kP2, 1.0, 1.0, d, k);
    const double before = C(kP1, kP2, d), after = C(kP1 + c.dp1, kP2 + c.dp2, d);
    EXPECT_NEAR(after, (1.0 - k) * before, 1e-12) << "stiffness k must remove the fraction k of the error C";
}

TEST(Task4_3_ProjectDistance, OnePinnedEndpointTheOtherMovesAllTheWay) {
    const auto c = projectDistanceConstraint(kP1, kP2, 0.0, 2.0, 0.5, 1.0);
    EXPECT_EQ(c.dp1.norm(), 0.0) << "p1 is pinned (w1 = 0) and must not move";
    EXPECT_NEAR(C(kP1, kP2 + c.dp2, 0.5), 0.0, 1e-12) << "with p1 pinned, p2 must move the whole way";
    const auto c2 = projectDistanceConstraint(kP1, kP2, 3.0, 0.0, 2.0, 1.0);
    EXPECT_EQ(c2.dp2.norm(), 0.0) << "p2 is pinned (w2 = 0) and must not move";
    EXPECT_NEAR(C(kP1 + c2.dp1, kP2, 2.0), 0.0, 1e-12) << "with p2 pinned, p1 must move the whole way";
}

TEST(Task4_3_ProjectDistance, BothPinnedNoMoveNoNaN) {
    const auto c = projectDistanceConstraint(kP1, kP2, 0.0, 0.0, 0.5, 1.0);
    EXPECT_TRUE(c.dp1.allFinite() && c.dp2.allFinite()) << "both pinned: division by w1 + w2 = 0 gives NaN";
    EXPECT_EQ(c.dp1.norm() + c.dp2.norm(), 0.0) << "both pinned: nothing may move";
}

TEST(Task4_3_ProjectDistance, CoincidentPointsNoMoveNoNaN) {
    const auto c = projectDistanceConstraint(kP1, kP1, 1.0, 1.0, 0.5, 1.0);
    EXPECT_TRUE(c.dp1.allFinite() && c.dp2.allFinite()) << "coincident points: division by |p1 - p2| = 0 gives NaN";
    EXPECT_EQ(c.dp1.norm() + c.dp2.norm(), 0.0) << "coincident points: the direction is undefined, do not move";
}

TEST(Task4_3_ProjectDistance, SatisfiedConstraintDoesNotMove) {
    const double d = std::sqrt(1.36);
    const auto c = projectDistanceConstraint(kP1, kP2, 1.0, 2.0, d, 1.0);
    EXPECT_LT(c.dp1.norm() + c.dp2.norm(), 1e-12) << "C = 0: the corrections must vanish";
}
