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
    EXPECT_CLOSE(distanceConstraint(kP1, kP2, 1.0), std::sqrt(1.36) - 1.0, 1e-12)
        << "the distance constraint C of p1, p2 at distance 1.16619 m with rest length d = 1 m, in m: it must measure how far "
           "the pair is stretched beyond d (positive when stretched)";
    EXPECT_CLOSE(distanceConstraint(kP1, kP2, 2.0), std::sqrt(1.36) - 2.0, 1e-12)
        << "the distance constraint C of p1, p2 at distance 1.16619 m with rest length d = 2 m, in m: a compressed pair "
           "(|p1 - p2| < d) must give minus the amount of compression";
    EXPECT_CLOSE(distanceConstraint(kP2, kP1, 1.0), std::sqrt(1.36) - 1.0, 1e-12)
        << "the distance constraint C with p1 and p2 swapped (d = 1 m), in m: a distance does not depend on the order of its "
           "end points";
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
        EXPECT_CLOSE(g[a], fd1, 1e-7) << "component " << a << " of the gradient of C with respect to p1: it must match the finite "
                                         "differences of C; your gradient is " << str(g);
        EXPECT_CLOSE(-g[a], fd2, 1e-7) << "component " << a << " of the gradient of C with respect to p2 (minus the returned one, "
                                          "as the header states): it must match the finite differences of C; your gradient is "
                                       << str(g);
    }
    EXPECT_CLOSE(g.norm(), 1.0, 1e-12) << "the length of the gradient of C, " << str(g)
                                       << ": a distance grows by 1 m per metre its end moves straight away, so it must be 1";
}

TEST(Task4_2_DistanceGradient, CoincidentPointsGiveZeroNotNaN) {
    const Vec3 g = distanceGradient(kP1, kP1);
    EXPECT_TRUE(g.allFinite()) << "the gradient of C for coincident points: it must be finite, not NaN or Inf; got " << str(g);
    EXPECT_EXACT(g.norm(), 0.0) << "the length of the gradient of C for coincident points: the direction is undefined, so the "
                                   "header requires the zero vector; got " << str(g);
}

// ---- Task 4.3 --------------------------------------------------------------------------
TEST(Task4_3_ProjectDistance, StiffnessOneSatisfiesTheConstraintExactly) {
    for (double d : {0.2, 1.0, 1.16619, 3.0}) {
        const auto c = projectDistanceConstraint(kP1, kP2, 2.0, 0.5, d, 1.0);
        const double constraintAfter = C(kP1 + c.dp1, kP2 + c.dp2, d);
        EXPECT_CLOSE(constraintAfter, 0.0, 1e-12)
            << "the constraint C after one projection with k = 1 (d = " << d << " m, w1 = 2, w2 = 0.5), in m: a fully stiff "
               "projection must satisfy the constraint, |p1 - p2| = d; dp1 = " << str(c.dp1) << ", dp2 = " << str(c.dp2);
    }
}

TEST(Task4_3_ProjectDistance, MovesAlongTheConstraintDirection) {
    const auto c = projectDistanceConstraint(kP1, kP2, 1.0, 1.0, 0.5, 1.0);
    const Vec3 n = (kP1 - kP2).normalized();
    const double dp1Sideways = (c.dp1 - c.dp1.dot(n) * n).norm();
    EXPECT_LESS(dp1Sideways, 1e-12) << "the part of the correction dp1 = " << str(c.dp1) << " across the line p1 - p2, in m: a "
                                       "projection moves along the constraint's gradient, so it must be parallel to p1 - p2";
    EXPECT_LESS(c.dp1.dot(n), 0.0) << "the component of dp1 = " << str(c.dp1) << " along the unit vector from p2 to p1, in m: a "
                                      "stretched constraint (d = 0.5 m) must pull p1 towards p2";
    EXPECT_GREATER(c.dp2.dot(n), 0.0) << "the component of dp2 = " << str(c.dp2) << " along the unit vector from p2 to p1, in m: a "
                                         "stretched constraint (d = 0.5 m) must pull p2 towards p1";
}

TEST(Task4_3_ProjectDistance, ConservesMomentum) {
    const double w1 = 4.0, w2 = 0.25;  // m1 = 0.25 kg, m2 = 4 kg
    const auto c = projectDistanceConstraint(kP1, kP2, w1, w2, 0.4, 0.7);
    const Vec3 momentum = c.dp1 / w1 + c.dp2 / w2;
    EXPECT_LESS(momentum.norm(), 1e-12) << "the momentum the projection creates, sum m_i dp_i (m1 = 0.25 kg, m2 = 4 kg), in kg m: "
                                           "a projection creates no momentum, so it must be zero; got " << str(momentum);
    const double correctionRatio = c.dp1.norm() / c.dp2.norm();
    EXPECT_CLOSE(correctionRatio, w1 / w2, 1e-9) << "the ratio |dp1| / |dp2| of the corrections of a 0.25 kg and a 4 kg particle: "
                                                    "with no momentum created the light one must move 16 times as far";
}

TEST(Task4_3_ProjectDistance, StiffnessScalesTheCorrection) {
    const double d = 0.5, k = 0.3;
    const auto c = projectDistanceConstraint(kP1, kP2, 1.0, 1.0, d, k);
    const double before = C(kP1, kP2, d), after = C(kP1 + c.dp1, kP2 + c.dp2, d);
    EXPECT_CLOSE(after, (1.0 - k) * before, 1e-12) << "the constraint C after one projection with stiffness k = 0.3, in m: it must "
                                                      "remove the fraction k of the error C = " << before << " m before";
}

TEST(Task4_3_ProjectDistance, OnePinnedEndpointTheOtherMovesAllTheWay) {
    const auto c = projectDistanceConstraint(kP1, kP2, 0.0, 2.0, 0.5, 1.0);
    EXPECT_EXACT(c.dp1.norm(), 0.0) << "the length of the correction of the pinned p1 (w1 = 0), in m: a pinned particle never "
                                       "moves; dp1 = " << str(c.dp1);
    const double afterP1Pinned = C(kP1, kP2 + c.dp2, 0.5);
    EXPECT_CLOSE(afterP1Pinned, 0.0, 1e-12) << "the constraint C after a projection with k = 1 and p1 pinned, in m: p2 must move "
                                               "the whole way, so C must be zero; dp2 = " << str(c.dp2);
    const auto c2 = projectDistanceConstraint(kP1, kP2, 3.0, 0.0, 2.0, 1.0);
    EXPECT_EXACT(c2.dp2.norm(), 0.0) << "the length of the correction of the pinned p2 (w2 = 0), in m: a pinned particle never "
                                        "moves; dp2 = " << str(c2.dp2);
    const double afterP2Pinned = C(kP1 + c2.dp1, kP2, 2.0);
    EXPECT_CLOSE(afterP2Pinned, 0.0, 1e-12) << "the constraint C after a projection with k = 1 and p2 pinned, in m: p1 must move "
                                               "the whole way, so C must be zero; dp1 = " << str(c2.dp1);
}

TEST(Task4_3_ProjectDistance, BothPinnedNoMoveNoNaN) {
    const auto c = projectDistanceConstraint(kP1, kP2, 0.0, 0.0, 0.5, 1.0);
    EXPECT_TRUE(c.dp1.allFinite() && c.dp2.allFinite()) << "the corrections when both ends are pinned (w1 = w2 = 0): they must "
                                                           "be finite, not NaN; dp1 = " << str(c.dp1) << ", dp2 = " << str(c.dp2);
    EXPECT_EXACT(c.dp1.norm() + c.dp2.norm(), 0.0) << "the total length |dp1| + |dp2| of the corrections when both ends are pinned, "
                                                      "in m: pinned particles never move, so it must be zero";
}

TEST(Task4_3_ProjectDistance, CoincidentPointsNoMoveNoNaN) {
    const auto c = projectDistanceConstraint(kP1, kP1, 1.0, 1.0, 0.5, 1.0);
    EXPECT_TRUE(c.dp1.allFinite() && c.dp2.allFinite()) << "the corrections for coincident points: they must be finite, not NaN; "
                                                           "dp1 = " << str(c.dp1) << ", dp2 = " << str(c.dp2);
    EXPECT_EXACT(c.dp1.norm() + c.dp2.norm(), 0.0) << "the total length |dp1| + |dp2| of the corrections for coincident points, "
                                                      "in m: the direction is undefined, so the header requires no move";
}

TEST(Task4_3_ProjectDistance, SatisfiedConstraintDoesNotMove) {
    const double d = std::sqrt(1.36);
    const auto c = projectDistanceConstraint(kP1, kP2, 1.0, 2.0, d, 1.0);
    const double totalCorrection = c.dp1.norm() + c.dp2.norm();
    EXPECT_LESS(totalCorrection, 1e-12) << "the total length |dp1| + |dp2| of the corrections of a satisfied constraint (C = 0), "
                                           "in m: nothing to correct, so they must vanish; dp1 = " << str(c.dp1) << ", dp2 = "
                                        << str(c.dp2);
}

// ============================ Randomised property tests =======================================
// Random orientations, scales from 1 mm to 100 m, random inverse masses and stiffnesses; seeds
// 1..kPropertySeeds (test_util.h). Expected behaviour from geometry and physics, not from your code.

namespace {
using testing_util::forEachSeed;
using testing_util::RandomGeometry;

// A random constraint: p1, p2 at distance len along a random direction, rest length d, both in metres.
struct RandomPair {
    double s, len, d;
    Vec3 p1, p2;
    RandomPair(RandomGeometry& G, double lenFactor) {
        s = G.scale();
        len = lenFactor * s;
        d = s * G.uniform(0.1, 3.0);
        p1 = G.point(5.0 * s);
        p2 = p1 + len * G.unitVector();
        len = (p1 - p2).norm();  // after rounding
    }
};
}  // namespace

TEST(Task4_1_DistanceConstraint, RandomOrientationsAndScales) {
    // C is a length: it does not change when the pair is rotated or moved, and it scales with the pair.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        RandomPair c(G, G.uniform(0.1, 3.0));
        const Eigen::Matrix3d R = G.rotation();
        const Vec3 t = G.point(c.s);
        const double want = C(c.p1, c.p2, c.d), got = distanceConstraint(R * c.p1 + t, R * c.p2 + t, c.d);
        if (std::abs(got - want) > 1e-12 * (c.len + c.d + c.p1.norm()))
            return testing::AssertionFailure() << "C = |p1 - p2| - d must not depend on the orientation or position of the pair: "
                                                  "p1 = " << str(R * c.p1 + t) << ", p2 = " << str(R * c.p2 + t) << ", d = " << c.d
                                               << " m: expected " << want << " m, got " << got << " m.";
        return testing::AssertionSuccess();
    });
}

TEST(Task4_2_DistanceGradient, RandomOrientationsScalesAndNearlyCoincidentPoints) {
    // The gradient of a distance is the unit vector from p2 to p1: checked by finite differences for pairs
    // 0.1 s to 3 s apart, and for nearly coincident (1e-9 m to 1e-4 m apart, but not coincident) pairs by its
    // length 1 and its direction.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        RandomPair c(G, G.uniform(0.1, 3.0));
        const Vec3 g = distanceGradient(c.p1, c.p2);
        const double h = 1e-6 * c.s;
        for (int a = 0; a < 3; ++a) {
            Vec3 e = Vec3::Zero();
            e[a] = h;
            const double fd = (C(c.p1 + e, c.p2, c.d) - C(c.p1 - e, c.p2, c.d)) / (2 * h);
            if (!std::isfinite(g[a]) || std::abs(g[a] - fd) > 1e-6)
                return testing::AssertionFailure() << "grad_p1 C must match finite differences for a pair of any size and "
                                                      "orientation: p1 = " << str(c.p1) << ", p2 = " << str(c.p2)
                                                   << ": component " << a << " is " << g[a] << ", finite differences give " << fd << ".";
        }
        const Vec3 p2 = c.p1 + G.logUniform(1e-9, 1e-4) * G.unitVector();
        const Vec3 e = c.p1 - p2;
        const Vec3 gn = distanceGradient(c.p1, p2);
        if (!gn.allFinite() || std::abs(gn.norm() - 1.0) > 1e-9 || std::abs(gn.dot(e) - e.norm()) > 1e-9 * e.norm())
            return testing::AssertionFailure()
                   << "Two points " << e.norm() << " m apart are close but not coincident: the gradient must still be the unit "
                      "vector (p1 - p2)/|p1 - p2| = " << str(e / e.norm()) << ", got " << str(gn)
                   << " (p1 = " << str(c.p1) << ", p2 = " << str(p2) << "). Only coincident points (|p1 - p2| < 1e-12 m) have "
                      "no direction; an absolute tolerance like 1e-6 m is too large for small cloths.";
        return testing::AssertionSuccess();
    });
}

TEST(Task4_3_ProjectDistance, RandomOrientationsScalesAndMasses) {
    // For random pairs (1 mm to 100 m), inverse masses (ratios up to 1e6, sometimes one pinned) and stiffness
    // k: the projection removes the fraction k of C, moves only along p1 - p2, keeps the momentum
    // sum m_i dp_i = 0 and the angular momentum sum p_i x m_i dp_i = 0, and a pinned particle stays put.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        RandomPair c(G, G.uniform(0.1, 3.0));
        double w1 = G.logUniform(1e-3, 1e3), w2 = G.logUniform(1e-3, 1e3);
        const int pin = static_cast<int>(G.uniform(0.0, 4.0));  // 0: pin p1, 1: pin p2, else none
        if (pin == 0) w1 = 0.0;
        if (pin == 1) w2 = 0.0;
        const double k = G.uniform(0.05, 1.0);
        const auto r = projectDistanceConstraint(c.p1, c.p2, w1, w2, c.d, k);
        const double before = C(c.p1, c.p2, c.d), after = C(c.p1 + r.dp1, c.p2 + r.dp2, c.d);
        std::ostringstream in;
        in << "p1 = " << str(c.p1) << ", p2 = " << str(c.p2) << ", w1 = " << w1 << ", w2 = " << w2 << " 1/kg, d = " << c.d
           << " m, k = " << k;
        if (!r.dp1.allFinite() || !r.dp2.allFinite() || std::abs(after - (1.0 - k) * before) > 1e-9 * (c.len + c.d))
            return testing::AssertionFailure() << "A projection with stiffness k must leave the fraction (1 - k) of the error C: "
                                               << in.str() << ": C went from " << before << " m to " << after << " m, expected "
                                               << (1.0 - k) * before << " m.";
        const Vec3 n = (c.p1 - c.p2) / c.len;
        if ((r.dp1 - r.dp1.dot(n) * n).norm() > 1e-9 * r.dp1.norm() + 1e-15 * c.s ||
            (r.dp2 - r.dp2.dot(n) * n).norm() > 1e-9 * r.dp2.norm() + 1e-15 * c.s)
            return testing::AssertionFailure() << "The corrections must lie along p1 - p2 (the constraint's gradient), in any "
                                                  "orientation: " << in.str() << ": dp1 = " << str(r.dp1) << ", dp2 = " << str(r.dp2) << ".";
        if ((w1 == 0.0 && r.dp1.norm() != 0.0) || (w2 == 0.0 && r.dp2.norm() != 0.0))
            return testing::AssertionFailure() << "A pinned particle (w = 0) must not move: " << in.str() << ": dp1 = " << str(r.dp1)
                                               << ", dp2 = " << str(r.dp2) << ".";
        if (w1 > 0 && w2 > 0) {
            const Vec3 P = r.dp1 / w1 + r.dp2 / w2, L = c.p1.cross(r.dp1) / w1 + c.p2.cross(r.dp2) / w2;
            const double scale = r.dp1.norm() / w1 + r.dp2.norm() / w2;
            if (P.norm() > 1e-9 * scale || L.norm() > 1e-9 * scale * (c.p1.norm() + c.p2.norm()))
                return testing::AssertionFailure() << "The projection must create no momentum (sum m_i dp_i = 0) and no angular "
                                                      "momentum (sum p_i x m_i dp_i = 0): "
                                                   << in.str() << ": sum m_i dp_i = " << str(P) << ", sum p_i x m_i dp_i = " << str(L) << ".";
        }
        return testing::AssertionSuccess();
    });
}

TEST(Task4_3_ProjectDistance, NearlyCoincidentPointsArePushedApart) {
    // Points 1e-9 m to 1e-4 m apart (close, not coincident) with a rest length of 0.1 s to 3 s: the constraint
    // is badly compressed and one projection with k = 1 must push them apart to exactly d.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        RandomPair c(G, 0.0);
        const Vec3 p2 = c.p1 + G.logUniform(1e-9, 1e-4) * G.unitVector();
        const double w1 = G.logUniform(1e-2, 1e2), w2 = G.logUniform(1e-2, 1e2);
        const auto r = projectDistanceConstraint(c.p1, p2, w1, w2, c.d, 1.0);
        const double after = (c.p1 + r.dp1 - p2 - r.dp2).norm();
        if (!r.dp1.allFinite() || !r.dp2.allFinite() || std::abs(after - c.d) > 1e-9 * c.d)
            return testing::AssertionFailure()
                   << "Two points only " << (c.p1 - p2).norm() << " m apart (close, but not coincident) with rest length d = "
                   << c.d << " m must be pushed apart to exactly d by one projection with k = 1; the distance afterwards is "
                   << after << " m (p1 = " << str(c.p1) << ", p2 = " << str(p2) << ", w1 = " << w1 << ", w2 = " << w2
                   << "). Only coincident points (|p1 - p2| < 1e-12 m) have no direction.";
        return testing::AssertionSuccess();
    });
}

// ---- Bonus 4.4: long-range attachments (optional) -------------------------------------------------
namespace {
/// Rest positions of `n` particles in a row along x, `spacing` m apart.
Matrix3X row(int n, double spacing) {
    Matrix3X x = Matrix3X::Zero(3, n);
    for (int i = 0; i < n; ++i) x(0, i) = spacing * i;
    return x;
}
std::string list(const std::vector<int>& v) {
    std::ostringstream o;
    for (size_t i = 0; i < v.size(); ++i) o << (i ? ", " : "[") << v[i];
    return o.str() + "]";
}
}  // namespace

TEST(Bonus4_4_TetherAnchors, NearestPinnedParticleLowestIndexOnTies) {
    // A row x = 0, 0.25, ..., 1.25 m pinned at particles 1 and 5: 3 is 0.5 m from both (tie: the lower index, 1).
    // (Spacings of 0.25 m keep every distance exact in binary floating point, so the tie is a tie.)
    VectorX w = VectorX::Ones(6);
    w[1] = w[5] = 0.0;
    const std::vector<int> want = {1, -1, 1, 1, 5, -1};
    EXPECT_EQ(list(tetherAnchors(row(6, 0.25), w)), list(want))
        << "the anchors of a row of 6 particles 0.25 m apart pinned at 1 and 5: each free particle's anchor is the nearest "
           "pinned one (of equally near ones the lower index), a pinned particle has none (-1)";
    // A 3 x 3 grid (0.25 m, index = 3 row + column) pinned at its top corners 0 and 2.
    Matrix3X grid(3, 9);
    for (int i = 0; i < 9; ++i) grid.col(i) = Vec3(0.25 * (i % 3), -0.25 * (i / 3), 0.0);
    w = VectorX::Ones(9);
    w[0] = w[2] = 0.0;
    const std::vector<int> want_grid = {-1, 0, -1, 0, 0, 2, 0, 0, 2};
    EXPECT_EQ(list(tetherAnchors(grid, w)), list(want_grid))
        << "the anchors of a 3 x 3 grid (0.25 m, index = 3 row + column) pinned at its top corners 0 and 2: the nearest pinned "
           "particle by rest distance, the lower index on a tie (the middle column)";
}

TEST(Bonus4_4_TetherAnchors, NoneWhenNothingIsPinned) {
    EXPECT_EQ(list(tetherAnchors(row(4, 0.1), VectorX::Ones(4))), list({-1, -1, -1, -1}))
        << "the anchors of 4 free particles and no pinned one: there is no pin to tie them to, every entry is -1";
    EXPECT_EQ(tetherAnchors(Matrix3X(3, 0), VectorX(0)).size(), 0u) << "the anchors of no particles: an empty list";
}

TEST(Bonus4_4_ProjectTether, SlackTetherMovesNothing) {
    const Vec3 a(0.1, 0.2, -0.3), p = a + Vec3(0.3, -0.4, 0.0);  // 0.5 m from the anchor
    EXPECT_EXACT(projectTether(p, a, 0.7).norm(), 0.0) << "a tether of length 0.7 m with its particle 0.5 m from the anchor is "
                                                          "slack: a one-sided constraint C <= 0 that holds moves nothing";
    EXPECT_EXACT(projectTether(a, a, 0.7).norm(), 0.0) << "a particle on its anchor (a tether of 0.7 m): slack, no move, no NaN";
    EXPECT_EXACT(projectTether(a, a, 0.0).norm(), 0.0) << "a particle on its anchor with a tether of length 0: the "
                                                          "constraint holds (C = 0), no move, no NaN";
}

TEST(Bonus4_4_ProjectTether, TautTetherEndsExactlyAtItsLength) {
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const Vec3 a = G.logUniform(1e-2, 1e2) * G.unitVector();
        const double L = G.logUniform(1e-3, 10.0), len = L * G.uniform(1.001, 3.0);
        const Vec3 p = a + len * G.unitVector();
        const Vec3 dp = projectTether(p, a, L);
        const double after = (p + dp - a).norm();
        const Vec3 toward = (a - p).normalized();
        if (!dp.allFinite() || std::abs(after - L) > 1e-9 * (L + a.norm()) ||
            (dp - dp.dot(toward) * toward).norm() > 1e-9 * dp.norm() + 1e-12 * (len + a.norm()) ||
            dp.dot(toward) <= 0)
            return testing::AssertionFailure() << "A taut tether (length L = " << L << " m, the particle " << len
                                               << " m from its anchor " << str(a) << ") must move the particle straight towards "
                                                  "the anchor until it is exactly L away; dp = " << str(dp)
                                               << ", distance afterwards " << after << " m.";
        const Vec3 onto = projectTether(p, a, 0.0);
        if (!onto.allFinite() || (p + onto - a).norm() > 1e-9 * (len + a.norm()))
            return testing::AssertionFailure() << "A tether of length 0 must pull the particle onto its anchor " << str(a)
                                               << "; it ends at " << str(p + onto) << ".";
        return testing::AssertionSuccess();
    });
}

TEST(Bonus4_4_Tethers, HangingChainStretchesNoFartherThanAtRest) {
    // A chain of 20 particles, 0.05 m apart, pinned at its first end, released horizontally under gravity and
    // simulated with PBD (your 4.3 at k = 1, 2 iterations, dt = 1/60 s) for 2 s. With 2 iterations the chain
    // stretches; tethers of the rest distance to the pin, projected after the links, must hold every particle
    // within its rest distance of the pin.
    const int n = 20;
    const Matrix3X rest = row(n, 0.05);
    VectorX w = VectorX::Ones(n);
    w[0] = 0.0;
    const std::vector<int> anchor = tetherAnchors(rest, w);
    ASSERT_EQ(anchor.size(), static_cast<size_t>(n)) << "tetherAnchors must give one anchor per particle";
    for (int i = 0; i < n; ++i)
        ASSERT_TRUE(anchor[i] >= -1 && anchor[i] < n) << "anchor " << i << " is " << anchor[i] << ": not a particle index or -1";
    auto simulate = [&](bool tethers) {
        Matrix3X x = rest, v = Matrix3X::Zero(3, n);
        double worst = 0.0;  // the largest distance to the pin over the rest distance, over all steps
        const double dt = 1.0 / 60.0;
        for (int step = 0; step < 120; ++step) {
            Matrix3X p = x;
            for (int i = 1; i < n; ++i) p.col(i) += dt * (v.col(i) + dt * Vec3(0, -9.81, 0));
            for (int it = 0; it < 2; ++it)
                for (int i = 0; i + 1 < n; ++i) {
                    const auto c = projectDistanceConstraint(p.col(i), p.col(i + 1), w[i], w[i + 1], 0.05, 1.0);
                    p.col(i) += c.dp1;
                    p.col(i + 1) += c.dp2;
                }
            if (tethers)
                for (int i = 0; i < n; ++i)
                    if (anchor[i] >= 0) p.col(i) += projectTether(p.col(i), p.col(anchor[i]), (rest.col(i) - rest.col(anchor[i])).norm());
            v = (p - x) / dt;
            x = p;
            for (int i = 1; i < n; ++i) worst = std::max(worst, (x.col(i) - x.col(0)).norm() / (0.05 * i));
        }
        return worst;
    };
    const double loose = simulate(false);
    ASSERT_GREATER(loose, 1.02) << "(the test's own scenario: without tethers the chain must stretch, or the test shows nothing; "
                                   "with your 4.3 the largest distance to the pin over its rest distance was " << loose << ")";
    EXPECT_LESS_EQ(simulate(true), 1.0 + 1e-9) << "the largest distance of a chain particle to the pin over its rest distance, "
                                                  "with a tether per particle projected after the links in every step: a "
                                                  "tether must keep each particle within its rest distance of the pin";
}

// ================================ Experiment (answers.json) ===================================
// The stage's experiment (task sheet, "Experiment"): predict from theory, measure with your own code,
// explain the difference, in exercises/04_distance/answers.json. This test checks only that the file is
// complete and well formed; the numbers are graded by the instructor.
TEST(Experiments, AnswerFileIsComplete) {
    EXPECT_TRUE(testing_util::answerFileIsComplete("04_distance", {"link_strain_dt_0_01", "link_strain_dt_0_005"}, {"link_strain_dt_0_01", "link_strain_dt_0_005"}));
}
