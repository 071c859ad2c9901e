// Graded tests of stage 07 — self-collision with a spatial hash.
// Test names start with the task they check (Task7_4 = exercise 7.4). Points: 07_self_collision.points.json.
// The hash is checked against brute force (all N(N-1)/2 pairs) on random clouds at every scale; the
// separation against its definition, conservation of momentum, and a small PBD loop written here.
#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "clothlab/exercise/07_self_collision.h"
#include "clothlab/sim/sweeps.h"
#include "test_util.h"

using namespace clothlab;
using testing_util::forEachSeed;
using testing_util::RandomGeometry;
using testing_util::str;

namespace {

// A random cloud: n particles in a box of half-width a around a random centre.
Matrix3X cloud(RandomGeometry& G, int n, double a, double centre) {
    const Vec3 c = G.point(centre);
    Matrix3X p(3, n);
    for (int i = 0; i < n; ++i) p.col(i) = c + G.point(a);
    return p;
}

// Every pair closer than d, by brute force: (i, j), i < j.
std::set<std::pair<int, int>> bruteForcePairs(const Matrix3X& p, double d) {
    std::set<std::pair<int, int>> out;
    for (int i = 0; i < p.cols(); ++i)
        for (int j = i + 1; j < p.cols(); ++j)
            if ((p.col(i) - p.col(j)).norm() < d) out.insert({i, j});
    return out;
}

// Compares the pairs found with the brute-force set: none missed, none twice, none extra, i < j.
testing::AssertionResult samePairs(const std::vector<ParticlePair>& found, const Matrix3X& p, double d, const std::string& in) {
    const std::set<std::pair<int, int>> want = bruteForcePairs(p, d);
    std::set<std::pair<int, int>> seen;
    for (const ParticlePair& q : found) {
        if (q.i >= q.j || q.i < 0 || q.j >= p.cols())
            return testing::AssertionFailure() << "The pair (" << q.i << ", " << q.j << ") must have 0 <= i < j < N = " << p.cols()
                                               << ": " << in << ".";
        if (!seen.insert({q.i, q.j}).second)
            return testing::AssertionFailure() << "The pair (" << q.i << ", " << q.j << ") is reported twice; each pair must come once "
                                                  "(two of the 27 cells around a particle can share a bucket): " << in << ".";
        if (!want.count({q.i, q.j}))
            return testing::AssertionFailure() << "The pair (" << q.i << ", " << q.j << ") is " << (p.col(q.i) - p.col(q.j)).norm()
                                               << " m apart, not closer than d = " << d << " m: " << in << ".";
    }
    for (const auto& [i, j] : want)
        if (!seen.count({i, j}))
            return testing::AssertionFailure() << "The pair (" << i << ", " << j << "), " << (p.col(i) - p.col(j)).norm()
                                               << " m apart (d = " << d << " m), is missed (brute force over all pairs finds "
                                               << want.size() << " pairs, the hash " << found.size() << "): " << in << ".";
    return testing::AssertionSuccess();
}

// The bucket that holds particle i in the hash (-1 if none).
int bucketOf(const SpatialHash& h, int i) {
    for (size_t b = 0; b + 1 < h.cellStart.size(); ++b)
        for (int k = h.cellStart[b]; k < h.cellStart[b + 1]; ++k)
            if (h.cellEntries[static_cast<size_t>(k)] == i) return static_cast<int>(b);
    return -1;
}

// The fraction of the T buckets that no cell of the block hits.
double emptyFraction(const std::vector<Eigen::Vector3i>& block, int T) {
    std::vector<char> used(static_cast<size_t>(T), 0);
    for (const auto& c : block) {
        const int b = hashCell(c, T);
        if (b >= 0 && b < T) used[static_cast<size_t>(b)] = 1;
    }
    return 1.0 - static_cast<double>(std::count(used.begin(), used.end(), 1)) / T;
}

}  // namespace

// ---- Task 7.1 ------------------------------------------------------------------------------------
TEST(Task7_1_CellOf, RoundsTowardsMinusInfinity) {
    const Eigen::Vector3i c = cellOf(Vec3(0.25, -0.2, 1.0), 0.5);
    EXPECT_EQ(c.x(), 0) << "the x cell of x = 0.25 m with cells of 0.5 m: 0.25 / 0.5 = 0.5 lies in cell 0";
    EXPECT_EQ(c.y(), -1) << "the y cell of y = -0.2 m with cells of 0.5 m: -0.4 rounded towards minus infinity is cell -1 "
                            "(rounding towards zero would put the cells -1 and 0 into one)";
    EXPECT_EQ(c.z(), 2) << "the z cell of z = 1.0 m with cells of 0.5 m: exactly on the boundary 2 s, which belongs to cell 2";
    const Eigen::Vector3i b = cellOf(Vec3(-0.5, -1e-9, -7.25), 0.5);
    EXPECT_EQ(b.x(), -1) << "the x cell of x = -0.5 m with cells of 0.5 m: exactly -1 s, the lower boundary of cell -1";
    EXPECT_EQ(b.y(), -1) << "the y cell of y = -1e-9 m: just below 0, cell -1";
    EXPECT_EQ(b.z(), -15) << "the z cell of z = -7.25 m with cells of 0.5 m: -14.5 rounded towards minus infinity is -15";
}

TEST(Task7_1_CellOf, EveryPointLiesInItsCell) {
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const double s = G.scale();
        for (int k = 0; k < 200; ++k) {
            const Vec3 p = G.point(300.0 * s);
            const Eigen::Vector3i c = cellOf(p, s);
            for (int a = 0; a < 3; ++a) {
                const double tol = 1e-12 * (std::abs(p[a]) + s);  // rounding of p / s near a cell boundary
                if (!(c[a] * s <= p[a] + tol && p[a] < (c[a] + 1) * s + tol))
                    return testing::AssertionFailure() << "The point " << str(p) << " m must lie in its cell: s c <= p < s (c + 1) per "
                                                          "coordinate with s = " << s << " m; coordinate " << a << " got cell " << c[a]
                                                       << ", which spans [" << c[a] * s << ", " << (c[a] + 1) * s << ") m.";
            }
        }
        return testing::AssertionSuccess();
    });
}

// ---- Task 7.2 ------------------------------------------------------------------------------------
TEST(Task7_2_HashCell, BucketsInTheTableForAnyCell) {
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const int T = static_cast<int>(G.logUniform(1.0, 2e6));
        for (int k = 0; k < 300; ++k) {
            const double range = G.logUniform(1.0, 1073741823.0);
            const Eigen::Vector3i c(static_cast<int>(G.uniform(-range, range)), static_cast<int>(G.uniform(-range, range)),
                                    static_cast<int>(G.uniform(-range, range)));
            const int b = hashCell(c, T);
            if (b < 0 || b >= T)
                return testing::AssertionFailure() << "The bucket of the cell (" << c.x() << ", " << c.y() << ", " << c.z()
                                                   << ") must lie in [0, T) with T = " << T << "; got " << b
                                                   << " (negative coordinates make a negative remainder in C++).";
            if (hashCell(c, T) != b)
                return testing::AssertionFailure() << "The same cell must always give the same bucket: (" << c.x() << ", " << c.y()
                                                   << ", " << c.z() << ") gave " << b << " and then " << hashCell(c, T) << ".";
        }
        return testing::AssertionSuccess();
    });
    EXPECT_EQ(hashCell(Eigen::Vector3i(-5, 7, 123456), 1), 0) << "the bucket of any cell in a table of one bucket: it must be 0";
}

TEST(Task7_2_HashCell, SpreadsBlocksOfCellsOverTheTable) {
    // T cells hashed into T buckets at random leave a fraction (1 - 1/T)^T = 1/e = 0.37 empty. A hash
    // that ignores a coordinate or adds the coordinates fills far fewer buckets: most cells collide.
    struct Block {
        const char* name;
        Eigen::Vector3i lo, size;
    };
    for (const Block& k : {Block{"a 16 x 16 x 16 cube at the origin", {0, 0, 0}, {16, 16, 16}},
                           Block{"a 64 x 64 x 1 slab (a flat cloth)", {-32, 5, 0}, {64, 64, 1}},
                           Block{"a 1 x 64 x 64 slab", {7, -20, -40}, {1, 64, 64}},
                           Block{"a 16 x 16 x 16 cube at negative coordinates", {-300, -17, -1000}, {16, 16, 16}}}) {
        std::vector<Eigen::Vector3i> block;
        for (int x = 0; x < k.size.x(); ++x)
            for (int y = 0; y < k.size.y(); ++y)
                for (int z = 0; z < k.size.z(); ++z) block.push_back(k.lo + Eigen::Vector3i(x, y, z));
        for (int T : {4096, 4099}) {
            EXPECT_LESS(emptyFraction(block, T), 0.45)
                << "the fraction of the " << T << " buckets left empty by " << k.name << " (" << block.size()
                << " cells): cells spread like random numbers leave about 1/e = 0.37 empty; far more means many cells share a "
                   "bucket (does the hash use all three coordinates, and mix them?)";
        }
    }
}

// ---- Task 7.3 ------------------------------------------------------------------------------------
TEST(Task7_3_BuildSpatialHash, CountingSortOfEveryParticle) {
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const double s = G.scale();
        const int n = static_cast<int>(G.uniform(0, 300)), T = static_cast<int>(G.uniform(1, 2.0 * n + 2));
        const Matrix3X p = cloud(G, n, 5.0 * s, 10.0 * s);
        const SpatialHash h = buildSpatialHash(p, s, T);
        std::ostringstream in;
        in << n << " particles, spacing s = " << s << " m, T = " << T << " buckets";
        if (h.cellStart.size() != static_cast<size_t>(T) + 1 || h.cellEntries.size() != static_cast<size_t>(n))
            return testing::AssertionFailure() << "cellStart must have T + 1 = " << T + 1 << " entries and cellEntries N = " << n
                                               << "; got " << h.cellStart.size() << " and " << h.cellEntries.size() << ": " << in.str() << ".";
        if (std::abs(h.spacing - s) > 1e-15 * s)
            return testing::AssertionFailure() << "spacing must be the cell size s = " << s << " m; got " << h.spacing << ": " << in.str() << ".";
        if (h.cellStart.front() != 0 || h.cellStart.back() != n || !std::is_sorted(h.cellStart.begin(), h.cellStart.end()))
            return testing::AssertionFailure() << "cellStart must start at 0, end at N = " << n << " and never decrease (offsets "
                                                  "of the buckets in cellEntries); it starts at " << h.cellStart.front() << " and ends at "
                                               << h.cellStart.back() << ": " << in.str() << ".";
        std::vector<int> sorted = h.cellEntries;
        std::sort(sorted.begin(), sorted.end());
        for (int i = 0; i < n; ++i)
            if (sorted[static_cast<size_t>(i)] != i)
                return testing::AssertionFailure() << "cellEntries must hold every particle index 0.." << n - 1 << " exactly once; index "
                                                   << i << " is missing or doubled: " << in.str() << ".";
        for (int i = 0; i < n; ++i) {
            const Vec3 q = p.col(i);
            const Eigen::Vector3i c(static_cast<int>(std::floor(q.x() / s)), static_cast<int>(std::floor(q.y() / s)),
                                    static_cast<int>(std::floor(q.z() / s)));
            const int want = hashCell(c, T), got = bucketOf(h, i);
            if (got != want)
                return testing::AssertionFailure() << "Particle " << i << " at " << str(q) << " lies in the cell (" << c.x() << ", "
                                                   << c.y() << ", " << c.z() << "), bucket hashCell = " << want
                                                   << "; the hash holds it in bucket " << got << ": " << in.str() << ".";
        }
        return testing::AssertionSuccess();
    });
}

// ---- Task 7.4 ------------------------------------------------------------------------------------
TEST(Task7_4_FindNeighbourPairs, SameAsBruteForceOnRandomClouds) {
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const double d = G.scale(), s = d * G.uniform(1.0, 2.0);
        const int n = static_cast<int>(G.uniform(2, 400)), T = static_cast<int>(G.logUniform(8.0, 3.0 * n + 8));
        const Matrix3X p = cloud(G, n, 3.0 * d, 20.0 * d);  // about 10 % of the particles have a neighbour
        const SpatialHash h = buildSpatialHash(p, s, T);
        std::ostringstream in;
        in << n << " random particles, d = " << d << " m, spacing " << s << " m, T = " << T << " buckets";
        return samePairs(findNeighbourPairs(p, h, d), p, d, in.str());
    });
}

TEST(Task7_4_FindNeighbourPairs, NoPairTwiceInATinyTable) {
    // With 1 or 2 buckets, many of the 27 cells around a particle share a bucket: a pair must still come once.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const double d = G.scale();
        const int n = static_cast<int>(G.uniform(2, 60)), T = 1 + static_cast<int>(seed % 3);
        const Matrix3X p = cloud(G, n, 1.5 * d, 5.0 * d);
        const SpatialHash h = buildSpatialHash(p, d, T);
        std::ostringstream in;
        in << n << " particles, d = spacing = " << d << " m, a table of T = " << T << " bucket(s)";
        return samePairs(findNeighbourPairs(p, h, d), p, d, in.str());
    });
}

TEST(Task7_4_FindNeighbourPairs, AFlatGridHasItsFourNeighbours) {
    // A flat n x n grid of spacing a, d = 1.2 a: the pairs are the 2 n (n - 1) grid edges (the diagonals are 1.41 a).
    const int n = 20;
    const double a = 0.03;
    Matrix3X p(3, n * n);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) p.col(r * n + c) = Vec3(-0.3 + c * a, 1.0, -0.2 + r * a);
    const std::vector<ParticlePair> found = findNeighbourPairs(p, buildSpatialHash(p, 1.2 * a, 2 * n * n), 1.2 * a);
    EXPECT_EQ(found.size(), static_cast<size_t>(2 * n * (n - 1)))
        << "the number of pairs closer than 1.2 a in a flat " << n << " x " << n << " grid of spacing a: each grid edge once";
    EXPECT_TRUE(samePairs(found, p, 1.2 * a, "a flat grid")) << "the pairs of a flat grid must be its edges, each once";
}

// ---- Task 7.5 ------------------------------------------------------------------------------------
TEST(Task7_5_ProjectSeparation, SeparatedToExactlyDWithMomentumKept) {
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const double s = G.scale(), d = s * G.uniform(0.1, 1.0);
        const double wi = G.logUniform(0.1, 10.0), wj = G.logUniform(0.1, 10.0);
        const Vec3 pi = G.point(10.0 * s), pj = pi + d * G.uniform(0.01, 0.99) * G.unitVector();
        const PairCorrection c = projectSeparation(pi, pj, wi, wj, d);
        std::ostringstream in;
        in << "p_i = " << str(pi) << ", p_j = " << str(pj) << " (" << (pi - pj).norm() << " m apart), d = " << d << " m, w_i = " << wi
           << ", w_j = " << wj << " 1/kg; got dp_i = " << str(c.dpi) << ", dp_j = " << str(c.dpj);
        const Vec3 u = (pi - pj).normalized();
        if (!c.dpi.allFinite() || !c.dpj.allFinite() || std::abs((pi + c.dpi - pj - c.dpj).norm() - d) > 1e-9 * d)
            return testing::AssertionFailure() << "After one projection the pair must be exactly d apart: they are "
                                               << (pi + c.dpi - pj - c.dpj).norm() << " m; " << in.str() << ".";
        if ((c.dpi - c.dpi.dot(u) * u).norm() > 1e-9 * d || (c.dpj - c.dpj.dot(u) * u).norm() > 1e-9 * d || c.dpi.dot(u) < 0)
            return testing::AssertionFailure() << "The corrections must push apart along the line through the pair, "
                                               << str(u) << " for p_i and the opposite for p_j; " << in.str() << ".";
        if ((c.dpi / wi + c.dpj / wj).norm() > 1e-9 * d / std::min(wi, wj))
            return testing::AssertionFailure() << "Momentum: m_i dp_i + m_j dp_j must be zero (shares by inverse mass); it is "
                                               << str(c.dpi / wi + c.dpj / wj) << " kg m; " << in.str() << ".";
        return testing::AssertionSuccess();
    });
}

TEST(Task7_5_ProjectSeparation, InequalityAndPinnedParticles) {
    const Vec3 pi(0, 0.05, 0), pj(0, 0, 0);
    const PairCorrection far = projectSeparation(pi, pj, 1.0, 1.0, 0.04);
    EXPECT_EXACT(far.dpi.norm() + far.dpj.norm(), 0.0)
        << "the corrections of a pair 0.05 m apart with d = 0.04 m, in m: the constraint is an inequality, it must never pull";
    const PairCorrection both = projectSeparation(pi, pj, 0.0, 0.0, 0.1);
    EXPECT_EXACT(both.dpi.norm() + both.dpj.norm(), 0.0) << "the corrections of two pinned particles (w = 0), in m: neither may move";
    const PairCorrection one = projectSeparation(pi, pj, 2.0, 0.0, 0.1);
    EXPECT_EXACT(one.dpj.norm(), 0.0) << "the correction of the pinned particle j (w_j = 0), in m: it must not move";
    EXPECT_CLOSE(pi.y() + one.dpi.y(), 0.1, 1e-12) << "the height of particle i after the projection against the pinned j, in m: "
                                                      "i alone must move, to d = 0.1 m from j";
}

TEST(Task7_5_ProjectSeparation, CoincidentParticlesGiveNoNaN) {
    for (const double gap : {0.0, 1e-300}) {
        const Vec3 pi(0.3, 0.2, -0.1), pj = pi + Vec3(gap, 0, 0);
        const PairCorrection c = projectSeparation(pi, pj, 1.0, 3.0, 0.02);
        EXPECT_TRUE(c.dpi.allFinite() && c.dpj.allFinite())
            << "the corrections of two particles " << gap << " m apart must be finite (the direction is then (0, 1, 0)); got dp_i = "
            << str(c.dpi) << ", dp_j = " << str(c.dpj);
        const Vec3 sep = (pi + c.dpi) - (pj + c.dpj);
        EXPECT_LESS((sep - Vec3(0, 0.02, 0)).norm(), 1e-12)
            << "the separation p_i - p_j after projecting two particles " << gap << " m apart, in m: the header's direction (0, 1, 0) "
               "times d = 0.02 m; got " << str(sep);
        EXPECT_LESS((c.dpi / 1.0 + c.dpj / 3.0).norm(), 1e-15)
            << "the momentum m_i dp_i + m_j dp_j of coincident particles, in kg m: it must be zero";
    }
}

// ---- Task 7.6 ------------------------------------------------------------------------------------
TEST(Task7_6_LayerFriction, LayersStickBelowMuTimesDepth) {
    // Particle i slid 1 cm along x over the step onto j, which stayed; the contact normal is y. mu depth = 0.5 x 4 cm = 2 cm > 1 cm.
    const Vec3 xi(0, 0.02, 0), pi(0.01, 0.02, 0), xj(0.01, 0, 0), pj(0.01, 0, 0);
    const PairCorrection c = layerFriction(pi, pj, xi, xj, 1.0, 1.0, 0.5, 0.04);
    const Vec3 rel = (pi + c.dpi - xi) - (pj + c.dpj - xj);
    EXPECT_LESS(std::abs(rel.x()), 1e-12) << "the relative slip of the layers along x after the friction, in m: 1 cm of slip is below "
                                             "mu depth = 2 cm, so the layers must stick (no relative slip); got " << str(rel);
    EXPECT_LESS((c.dpi + c.dpj).norm(), 1e-15) << "the momentum of equal masses, dp_i + dp_j, in kg m per unit mass: it must be zero; "
                                               << "got dp_i = " << str(c.dpi) << ", dp_j = " << str(c.dpj);
}

TEST(Task7_6_LayerFriction, LayersSlideSlowerAboveMuTimesDepth) {
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const double s = G.scale(), depth = s * G.uniform(0.01, 0.1), mu = G.uniform(0.05, 1.0);
        const double wi = G.logUniform(0.1, 10.0), wj = G.logUniform(0.1, 10.0);
        const Vec3 n = G.unitVector(), t = G.perpendicularTo(n);
        const Vec3 xj = G.point(10.0 * s), pj = xj + s * G.point(0.1);
        const Vec3 pi = pj + 0.9 * s * n;
        const double slip = mu * depth * G.uniform(1.2, 5.0);
        const Vec3 xi = pi - (pj - xj) - slip * t - s * G.uniform(-0.2, 0.2) * n;  // relative displacement: slip along t plus a normal part
        const PairCorrection c = layerFriction(pi, pj, xi, xj, wi, wj, mu, depth);
        const Vec3 relBefore = (pi - xi) - (pj - xj), relAfter = (pi + c.dpi - xi) - (pj + c.dpj - xj);
        const Vec3 tAfter = relAfter - relAfter.dot(n) * n;
        std::ostringstream in;
        in << "normal " << str(n) << ", tangential slip " << slip << " m along " << str(t) << ", mu = " << mu << ", depth = " << depth
           << " m, w_i = " << wi << ", w_j = " << wj << "; got dp_i = " << str(c.dpi) << ", dp_j = " << str(c.dpj);
        if (std::abs(tAfter.norm() - (slip - mu * depth)) > 1e-9 * s || tAfter.dot(t) < 0)
            return testing::AssertionFailure() << "Sliding: the tangential slip must shrink by mu depth = " << mu * depth << " m, from "
                                               << slip << " to " << slip - mu * depth << " m, in its own direction; it is " << str(tAfter)
                                               << " m; " << in.str() << ".";
        if (std::abs(relAfter.dot(n) - relBefore.dot(n)) > 1e-9 * s)
            return testing::AssertionFailure() << "Friction acts along the contact only: the normal part of the relative displacement "
                                                  "must stay " << relBefore.dot(n) << " m; it is " << relAfter.dot(n) << " m; " << in.str() << ".";
        if ((c.dpi / wi + c.dpj / wj).norm() > 1e-9 * s / std::min(wi, wj))
            return testing::AssertionFailure() << "Momentum: m_i dp_i + m_j dp_j must be zero; " << in.str() << ".";
        return testing::AssertionSuccess();
    });
}

TEST(Task7_6_LayerFriction, NothingWithoutFrictionContactOrFreeParticle) {
    const Vec3 xi(0, 0.02, 0), pi(0.01, 0.02, 0), xj(0, 0, 0), pj(0, 0, 0);
    const PairCorrection a = layerFriction(pi, pj, xi, xj, 1.0, 1.0, 0.0, 0.04);
    EXPECT_EXACT(a.dpi.norm() + a.dpj.norm(), 0.0) << "the friction corrections with mu = 0, in m: there must be none";
    const PairCorrection b = layerFriction(pi, pj, xi, xj, 1.0, 1.0, 0.5, 0.0);
    EXPECT_EXACT(b.dpi.norm() + b.dpj.norm(), 0.0) << "the friction corrections without contact (depth 0), in m: there must be none";
    const PairCorrection c = layerFriction(pi, pj, xi, xj, 0.0, 0.0, 0.5, 0.04);
    EXPECT_EXACT(c.dpi.norm() + c.dpj.norm(), 0.0) << "the friction corrections of two pinned particles, in m: there must be none";
    const PairCorrection e = layerFriction(pi, pi, xi, xi, 1.0, 1.0, 0.5, 0.04);
    EXPECT_TRUE(e.dpi.allFinite() && e.dpj.allFinite()) << "the friction corrections of coincident particles must be finite; got "
                                                        << str(e.dpi) << ", " << str(e.dpj);
}

// ---- Whole steps: a small PBD loop written here with your hash and separation ---------------------------
namespace {
// One step of particles under gravity g with self-collision only: predict, hash, pairs within 2h (a wide margin),
// `iterations` sweeps of the separation to h (the framework's sweep, sim/sweeps.h, calls your
// projectSeparation for every pair closer than h), then v = (p - x)/dt.
void selfCollisionStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const Vec3& g, double h, double dt, int iterations) {
    for (int i = 0; i < x.cols(); ++i)
        if (w[i] > 0) v.col(i) += dt * g;
    Matrix3X p = x + dt * v;
    const std::vector<ParticlePair> pairs = findNeighbourPairs(p, buildSpatialHash(p, 2.0 * h, 2 * static_cast<int>(x.cols())), 2.0 * h);
    for (int it = 0; it < iterations; ++it) projectSelfCollisionSweep(pairs, h, x, w, 0.0, p);  // your projectSeparation per pair
    v = (p - x) / dt;
    x = p;
}

}  // namespace

// Also the instructor's experiment of this stage (tests/instructor/experiments/07_self_collision.cpp).
namespace stage07 {
// Two n x n layers of spacing h: the lower one pinned, the upper one dropped from 5 h above it, shifted
// by half a spacing, so that each of its particles lands on four of the lower layer; `steps` steps of
// dt = 5 ms. Returns the closest distance between
// a particle of the upper layer and one of the lower layer at the end, m.
double dropLayerOnLayer(int n, double h, int steps, int iterations) {
    const double a = h, dt = 0.005;
    Matrix3X x(3, 2 * n * n), v = Matrix3X::Zero(3, 2 * n * n);
    VectorX w(2 * n * n);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            x.col(r * n + c) = Vec3(c * a, 0, r * a);
            w[r * n + c] = 0.0;
            x.col(n * n + r * n + c) = Vec3((c + 0.5) * a, 5.0 * h, (r + 0.5) * a);
            w[n * n + r * n + c] = 1.0;
        }
    for (int k = 0; k < steps; ++k) selfCollisionStep(x, v, w, Vec3(0, -9.81, 0), h, dt, iterations);
    double closest = x.allFinite() ? INFINITY : std::nan("");
    for (int i = 0; i < n * n; ++i)
        for (int j = n * n; j < 2 * n * n; ++j) closest = std::min(closest, (x.col(i) - x.col(j)).norm());
    return closest;
}
}  // namespace stage07
using stage07::dropLayerOnLayer;

TEST(Task7_5_SelfCollisionSteps, AFallingLayerRestsOnTheLowerOne) {
    // After 0.5 s the upper layer rests on the lower one: no particle of one closer than h to one of the
    // other (1 %, what 20 iterations leave of the last step), and not hovering above it.
    const double h = 0.01, closest = dropLayerOnLayer(12, h, 100, 20);
    EXPECT_TRUE(std::isfinite(closest)) << "the positions after dropping a layer onto a pinned one must stay finite";
    EXPECT_GREATER(closest, h * 0.99) << "the closest distance between the falling layer and the pinned one after 0.5 s, in m: "
                                               "the separation must hold them at least h = " << h << " m apart";
    EXPECT_LESS(closest, 1.5 * h) << "the closest distance between the layers after 0.5 s, in m: the upper layer must have come down "
                                     "and rest on the lower one (about h = " << h << " m), not hover";
}

TEST(Task7_5_SelfCollisionSteps, CollidingCloudsKeepTheirMomentum) {
    // Random particles with random masses and velocities in free space (no gravity), densely packed so
    // that many pairs overlap: self-collision is internal, the total momentum sum m v must not change.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const double h = G.scale(), dt = 0.01;
        const int n = static_cast<int>(G.uniform(20, 120));
        Matrix3X x = cloud(G, n, 2.0 * h, 10.0 * h), v(3, n);
        VectorX w(n);
        for (int i = 0; i < n; ++i) {
            v.col(i) = (h / dt) * G.point(0.3);
            w[i] = G.logUniform(0.2, 5.0);
        }
        const Vec3 before = v * w.cwiseInverse();
        for (int k = 0; k < 5; ++k) selfCollisionStep(x, v, w, Vec3::Zero(), h, dt, 3);
        const Vec3 after = v * w.cwiseInverse();
        const double scale = (h / dt) * w.cwiseInverse().sum();
        if (!v.allFinite() || (after - before).norm() > 1e-9 * scale)
            return testing::AssertionFailure() << "The total momentum sum m_i v_i of " << n << " particles colliding with each other (h = " << h
                                               << " m, no external force) must not change: " << str(before) << " before, " << str(after)
                                               << " kg m/s after 5 steps.";
        return testing::AssertionSuccess();
    });
}

// ================================ Experiment (answers.json) ===================================
// The stage's experiment (task sheet, "Experiment"): predict from theory, measure with your own code,
// explain the difference, in exercises/07_self_collision/answers.json. This test checks only that the file is
// complete and well formed; the numbers are graded by the instructor.
TEST(Experiments, AnswerFileIsComplete) {
    EXPECT_TRUE(testing_util::answerFileIsComplete("07_self_collision", {"rest_height"}, {"rest_height"}));
}
