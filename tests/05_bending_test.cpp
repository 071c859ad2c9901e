// Graded tests of stage 05 — the bending constraint and its stencils.
// Test names start with the task they check (Task5_2 = exercise 5.2). Points: 05_bending.points.json.
// The dihedral angle is computed here independently (normals of the two triangles), not with your code.
#include <cmath>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "clothlab/core/grid.h"
#include "clothlab/exercise/05_bending.h"
#include "test_util.h"

using namespace clothlab;

namespace {

constexpr double kPi = 3.14159265358979323846;

using testing_util::str;

// d = n1.n2 with n1 the normal of (p1, p2, p3) and n2 the normal of (p1, p2, p4), written independently.
double dOf(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
    const Vec3 n1 = (p2 - p1).cross(p3 - p1).normalized(), n2 = (p2 - p1).cross(p4 - p1).normalized();
    return n1.dot(n2);
}
double angleOf(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
    return std::acos(std::max(-1.0, std::min(1.0, dOf(p1, p2, p3, p4))));
}

// A stencil: the edge p1 = 0, p2 = (1, 0, 0) along x; p3 in the x-y plane at +y; p4 rotated by the
// angle `open` about the edge (open = pi: flat, p4 at -y).
struct Stencil {
    Vec3 p[4];
};
Stencil hinge(double open, double skew = 0.0) {
    Stencil s;
    s.p[0] = Vec3(0.05, -0.02, 0.01);
    s.p[1] = s.p[0] + Vec3(1.0, 0.0, 0.0);
    s.p[2] = s.p[0] + Vec3(0.4, 0.8, 0.0);
    s.p[3] = s.p[0] + Vec3(0.6 + skew, 0.7 * std::cos(open), 0.7 * std::sin(open));
    return s;
}

double angleAfter(const Stencil& s, const BendingCorrection& c) {
    return angleOf(s.p[0] + c.dp1, s.p[1] + c.dp2, s.p[2] + c.dp3, s.p[3] + c.dp4);
}

}  // namespace

// ---- Task 5.1 ------------------------------------------------------------------------------------
TEST(Task5_1_BendingGradients, DIsTheCosineOfTheDihedralAngle) {
    for (double open : {0.3, 1.0, 2.0, 2.9}) {
        const Stencil s = hinge(open, 0.1);
        const auto g = bendingGradients(s.p[0], s.p[1], s.p[2], s.p[3]);
        EXPECT_TRUE(g.valid) << "the valid flag of a proper stencil (two triangles of positive area, opening angle " << open
                             << " rad): it must be true";
        EXPECT_CLOSE(g.d, dOf(s.p[0], s.p[1], s.p[2], s.p[3]), 1e-12)
            << "d of a hinge with opening angle " << open << " rad: it must be the cosine of the angle between the two "
               "triangles' unit normals (orientation as in the header)";
    }
}

TEST(Task5_1_BendingGradients, QVectorsAreFiniteDifferenceGradientsOfD) {
    const double h = 1e-6;
    for (double open : {0.4, 1.3, 2.2, 2.8}) {
        Stencil s = hinge(open, -0.15);
        s.p[2] += Vec3(0.03, 0.0, 0.2);  // a general, non-symmetric stencil
        const auto g = bendingGradients(s.p[0], s.p[1], s.p[2], s.p[3]);
        const Vec3 q[4] = {g.q1, g.q2, g.q3, g.q4};
        for (int i = 0; i < 4; ++i)
            for (int a = 0; a < 3; ++a) {
                Stencil plus = s, minus = s;
                plus.p[i][a] += h;
                minus.p[i][a] -= h;
                const double fd = (dOf(plus.p[0], plus.p[1], plus.p[2], plus.p[3]) -
                                   dOf(minus.p[0], minus.p[1], minus.p[2], minus.p[3])) / (2 * h);
                EXPECT_CLOSE(q[i][a], fd, 1e-6) << "component " << a << " of q" << i + 1 << " = " << str(q[i])
                                               << " at opening angle " << open << " rad: q" << i + 1
                                               << " must be the gradient of d with respect to p" << i + 1
                                               << ", as finite differences measure it";
            }
    }
}

TEST(Task5_1_BendingGradients, SinPhiIsAccurateAlsoNearFlat) {
    // hinge(open) has the dihedral angle phi = open, so sin(phi) = sin(open), up to the rounding of the
    // positions (relative 1e-11 here). Near flat, sqrt(1 - d^2) cannot be this accurate: d ~ -1 is
    // rounded to 1e-16, and 1 - d^2 ~ (pi - phi)^2 keeps only a few digits of it.
    for (double open : {0.3, 1.0, 2.0, 2.9}) {
        const Stencil s = hinge(open, 0.1);
        const auto g = bendingGradients(s.p[0], s.p[1], s.p[2], s.p[3]);
        EXPECT_CLOSE(g.sinPhi, std::sin(open), 1e-12) << "sinPhi of a hinge with dihedral angle phi = " << open
                                                     << " rad: it must be sin(phi)";
    }
    for (double flatness : {1e-3, 1e-5, 2e-6}) {
        const double open = kPi - flatness;
        const Stencil s = hinge(open, -0.2);
        const auto g = bendingGradients(s.p[0], s.p[1], s.p[2], s.p[3]);
        EXPECT_CLOSE(g.sinPhi, std::sin(open), 1e-8 * std::sin(open))
            << "sinPhi of a nearly flat hinge, phi = pi - " << flatness << ": it must be accurate to 1e-8 relative also near "
               "flat (see the header); its relative error is " << g.sinPhi / std::sin(open) - 1;
    }
}

TEST(Task5_1_BendingGradients, ZeroAreaTriangleIsInvalidNotNaN) {
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(0.5, 1, 0), d(0.5, -1, 0.2);
    const auto g1 = bendingGradients(a, b, Vec3(2, 0, 0), d);  // p3 on the edge line
    const auto g2 = bendingGradients(a, a, c, d);              // p1 = p2
    for (const auto& g : {g1, g2}) {
        EXPECT_FALSE(g.valid) << "the valid flag of a stencil with a zero-area triangle: such a triangle has no normal, so it "
                                 "must be false";
        EXPECT_TRUE(std::isfinite(g.d) && g.q1.allFinite() && g.q2.allFinite() && g.q3.allFinite() && g.q4.allFinite())
            << "d and q1..q4 of a stencil with a zero-area triangle: they must be finite, not NaN; d = " << g.d << ", q1 = "
            << str(g.q1) << ", q2 = " << str(g.q2) << ", q3 = " << str(g.q3) << ", q4 = " << str(g.q4);
        EXPECT_EXACT(g.q1.norm() + g.q2.norm() + g.q3.norm() + g.q4.norm(), 0.0)
            << "the total length |q1| + ... + |q4| of an invalid stencil's gradients: the header requires all q to be zero";
        EXPECT_EXACT(g.sinPhi, 0.0) << "sinPhi of an invalid stencil: the header requires zero";
    }
}

// ---- Task 5.2 ------------------------------------------------------------------------------------
TEST(Task5_2_ProjectBending, ReducesTheErrorForSmallDeviations) {
    for (double phi0 : {1.0, 2.0, 2.6}) {
        for (double dev : {0.05, -0.05}) {
            const Stencil s = hinge(phi0 + dev, 0.1);
            const double before = angleOf(s.p[0], s.p[1], s.p[2], s.p[3]) - phi0;
            const auto c = projectBendingConstraint(s.p[0], s.p[1], s.p[2], s.p[3], 1, 1, 1, 1, phi0, 1.0);
            const double after = angleAfter(s, c) - phi0;
            const double errorAfter = std::abs(after), errorBefore = std::abs(before);
            EXPECT_LESS(errorAfter, 0.1 * errorBefore)
                << "the bending error |C| = |phi - phi0| in rad after one projection with k = 1, rest angle " << phi0
                << ", deviation " << dev << ": a small deviation must be almost removed (by 90 %); it went from "
                << errorBefore << " to " << errorAfter;
        }
    }
}

TEST(Task5_2_ProjectBending, ReducesTheErrorForMediumDeviations) {
    for (double phi0 : {1.2, 2.0}) {
        for (double dev : {0.5, -0.5}) {
            const Stencil s = hinge(phi0 + dev, -0.1);
            const double before = angleOf(s.p[0], s.p[1], s.p[2], s.p[3]) - phi0;
            const auto c = projectBendingConstraint(s.p[0], s.p[1], s.p[2], s.p[3], 1, 2, 0.5, 1, phi0, 1.0);
            const double after = angleAfter(s, c) - phi0;
            const double errorAfter = std::abs(after), errorBefore = std::abs(before);
            EXPECT_LESS(errorAfter, 0.5 * errorBefore)
                << "the bending error |C| = |phi - phi0| in rad after one projection with k = 1 and uneven masses, rest angle "
                << phi0 << ", deviation " << dev << ": it must at least halve; it went from " << errorBefore << " to "
                << errorAfter;
        }
    }
}

TEST(Task5_2_ProjectBending, NearlyFlatStencilFarFromItsRestAngle) {
    // A crease (rest angle pi - 0.5) pressed nearly flat, only p4 free. Rotating p4 about the edge by an
    // angle dphi moves it by h4 dphi (h4 = 0.7 m, its distance from the edge), so |grad_p4 C| = 1/h4 and
    // the PBD step moves p4 by exactly |C| / |grad_p4 C| = |C| h4, however flat the stencil is.
    const double phi0 = kPi - 0.5, h4 = 0.7;
    for (double flatness : {1e-4, 1e-5, 2e-6}) {
        const double open = kPi - flatness;
        const Stencil s = hinge(open, 0.1);
        const auto c = projectBendingConstraint(s.p[0], s.p[1], s.p[2], s.p[3], 0, 0, 0, 1, phi0, 1.0);
        const double expected = std::abs(open - phi0) * h4;
        EXPECT_CLOSE(c.dp4.norm(), expected, 1e-8 * expected)
            << "the length of the correction of p4 (the only free particle), in m, for a crease (rest angle pi - 0.5) pressed "
               "nearly flat, phi = pi - " << flatness << ": rotating p4 about the edge it must move |C| h4, however flat "
               "the stencil (see the header on accuracy near flat); relative error " << c.dp4.norm() / expected - 1;
        const double errorAfter = std::abs(angleAfter(s, c) - phi0);
        EXPECT_LESS(errorAfter, 0.5 * std::abs(open - phi0))
            << "the bending error |phi - phi0| in rad of the nearly flat crease after the projection: the crease must close, "
               "the error at least halve from " << std::abs(open - phi0);
    }
}

TEST(Task5_2_ProjectBending, ConservesLinearAndAngularMomentum) {
    const Stencil s = hinge(1.7, 0.2);
    const double w[4] = {1.0, 0.5, 2.0, 4.0};
    const auto c = projectBendingConstraint(s.p[0], s.p[1], s.p[2], s.p[3], w[0], w[1], w[2], w[3], 1.2, 0.8);
    const Vec3 dp[4] = {c.dp1, c.dp2, c.dp3, c.dp4};
    Vec3 P = Vec3::Zero(), L = Vec3::Zero();
    for (int i = 0; i < 4; ++i) {
        P += dp[i] / w[i];
        L += s.p[i].cross(dp[i] / w[i]);
    }
    EXPECT_GREATER(c.dp1.norm(), 1e-4) << "the length of the correction of p1, in m: the stencil is bent away from its rest angle "
                                          "(1.7 vs 1.2 rad), so it must move";
    EXPECT_LESS(P.norm(), 1e-12) << "the momentum the projection creates, sum m_i dp_i (masses 1, 2, 0.5, 0.25 kg): a projection "
                                    "creates no momentum, so it must be zero; got " << str(P);
    EXPECT_LESS(L.norm(), 1e-12) << "the angular momentum the projection creates, sum p_i x m_i dp_i: a projection creates no "
                                    "angular momentum, so it must be zero; got " << str(L);
}

TEST(Task5_2_ProjectBending, PinnedParticlesDoNotMove) {
    const Stencil s = hinge(1.7);
    const auto c = projectBendingConstraint(s.p[0], s.p[1], s.p[2], s.p[3], 0, 0, 1, 0, 1.2, 1.0);
    EXPECT_EXACT(c.dp1.norm() + c.dp2.norm() + c.dp4.norm(), 0.0)
        << "the total length |dp1| + |dp2| + |dp4| of the corrections of the pinned p1, p2, p4 (w = 0), in m: pinned particles "
           "never move; dp1 = " << str(c.dp1) << ", dp2 = " << str(c.dp2) << ", dp4 = " << str(c.dp4);
    EXPECT_GREATER(c.dp3.norm(), 0.0) << "the length of the correction of the free p3, in m: the stencil is bent away from its "
                                         "rest angle, and p3 is the only particle that can fix it, so it must move";
    const double errorAfter = std::abs(angleAfter(s, c) - 1.2);
    EXPECT_LESS(errorAfter, 0.5 * std::abs(1.7 - 1.2))
        << "the bending error |phi - phi0| in rad after moving p3 alone: it must at least halve from 0.5";
}

TEST(Task5_2_ProjectBending, StiffnessScalesTheCorrection) {
    const Stencil s = hinge(1.5);
    const auto c1 = projectBendingConstraint(s.p[0], s.p[1], s.p[2], s.p[3], 1, 1, 1, 1, 1.3, 1.0);
    const auto c2 = projectBendingConstraint(s.p[0], s.p[1], s.p[2], s.p[3], 1, 1, 1, 1, 1.3, 0.25);
    const double scalingError = (c2.dp3 - 0.25 * c1.dp3).norm();
    EXPECT_LESS(scalingError, 1e-12) << "the distance of dp3 at k = 0.25 from a quarter of dp3 at k = 1, in m: the stiffness k "
                                        "must scale the corrections; dp3 = " << str(c2.dp3) << " at k = 0.25, " << str(c1.dp3)
                                     << " at k = 1";
}

TEST(Task5_2_ProjectBending, DegenerateCasesGiveZeroNotNaN) {
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(0.5, 1, 0);
    struct Case { const char* what; Vec3 p1, p2, p3, p4; double w; };
    const Case cases[] = {
        {"flat stencil (d = -1)", a, b, c, Vec3(0.5, -1, 0), 1.0},
        {"folded stencil (d = +1)", a, b, c, Vec3(0.7, 2, 0), 1.0},
        {"zero-area triangle", a, b, Vec3(2, 0, 0), Vec3(0.5, -1, 0.3), 1.0},
        {"coincident points", a, a, a, a, 1.0},
        {"all particles pinned", a, b, c, Vec3(0.5, -0.5, 0.7), 0.0},
    };
    for (const Case& k : cases) {
        const auto r = projectBendingConstraint(k.p1, k.p2, k.p3, k.p4, k.w, k.w, k.w, k.w, 1.0, 1.0);
        const bool finite = r.dp1.allFinite() && r.dp2.allFinite() && r.dp3.allFinite() && r.dp4.allFinite();
        EXPECT_TRUE(finite) << "the corrections of a " << k.what << ": they must be finite, not NaN or Inf; dp1 = " << str(r.dp1)
                            << ", dp2 = " << str(r.dp2) << ", dp3 = " << str(r.dp3) << ", dp4 = " << str(r.dp4);
        if (finite) {
            EXPECT_EXACT(r.dp1.norm() + r.dp2.norm() + r.dp3.norm() + r.dp4.norm(), 0.0)
                << "the total length of the corrections of a " << k.what << ", in m: the header's convention for a degenerate "
                   "stencil is that nothing moves";
        }
    }
}

// ---- Task 5.3 ------------------------------------------------------------------------------------
TEST(Task5_3_BendingStencils, OneStencilPerInteriorEdge) {
    const int nx = 4, ny = 3;
    ClothSpec spec;
    spec.nx = nx, spec.ny = ny;
    const State st = makeGridState(spec);
    const auto tris = gridTriangles(nx, ny);
    const auto stencils = bendingStencils(tris, st.x);
    // Edges of the grid: horizontal, vertical, one diagonal per cell; boundary edges lie on the rim.
    const int edges = (nx - 1) * ny + nx * (ny - 1) + (nx - 1) * (ny - 1);
    const int boundary = 2 * (nx - 1) + 2 * (ny - 1);
    ASSERT_EQ(static_cast<int>(stencils.size()), edges - boundary)
        << "the number of bending stencils of a 4 x 3 grid: one per interior edge (an edge shared by two triangles), none for "
           "the rim";
    std::set<std::pair<int, int>> seen;
    for (const auto& s : stencils) {
        const auto e = std::minmax(s.i1, s.i2);
        EXPECT_TRUE(seen.insert(e).second) << "the stencils of edge " << e.first << "-" << e.second
                                           << ": an edge bends at one hinge, so it must have one stencil; it has more";
        // (i1, i2, i3) and (i1, i2, i4) must both be triangles of the mesh, i3 != i4.
        int found = 0;
        for (const auto& t : tris) {
            std::set<int> ts{t[0], t[1], t[2]};
            if (ts == std::set<int>{s.i1, s.i2, s.i3} || ts == std::set<int>{s.i1, s.i2, s.i4}) ++found;
        }
        EXPECT_EQ(found, 2) << "stencil (" << s.i1 << ", " << s.i2 << ", " << s.i3 << ", " << s.i4
                            << "): i3 and i4 must be the vertices opposite the edge i1-i2 in its two triangles";
        EXPECT_CLOSE(s.phi0, kPi, 1e-6) << "the rest angle phi0 of stencil (" << s.i1 << ", " << s.i2 << ", " << s.i3 << ", "
                                       << s.i4 << ") of a flat cloth, in rad: flat is pi (d = -1 with this convention)";
    }
}

namespace {
/// Two triangles (0, 1, 2) and (1, 0, 3) hinged on the edge 0-1, the fourth vertex at p3.
Matrix3X hinge(const Vec3& p3) {
    Matrix3X x(3, 4);
    x << 0, 1, 0.5, p3.x(),  //
        0, 0, 1, p3.y(),     //
        0, 0, 0, p3.z();
    return x;
}
const std::vector<Eigen::Vector3i> kHingeTriangles = {Eigen::Vector3i(0, 1, 2), Eigen::Vector3i(1, 0, 3)};
}  // namespace

TEST(Task5_3_BendingStencils, RestAnglesComeFromTheInitialShape) {
    // Two triangles folded by 90 degrees about the edge 0-1.
    const Matrix3X x = hinge(Vec3(0.5, 0, 1));
    const auto st = bendingStencils(kHingeTriangles, x);
    ASSERT_EQ(st.size(), 1u) << "the number of stencils of two triangles sharing one edge: one hinge, one stencil";
    EXPECT_CLOSE(st[0].phi0, angleOf(x.col(0), x.col(1), x.col(2), x.col(3)), 1e-12)
        << "the rest angle phi0 of two triangles folded by 90 degrees, in rad: the cloth rests in its initial shape, so phi0 "
           "must be the dihedral angle of the initial positions (here pi/2)";
}

TEST(Task5_3_BendingStencils, DegenerateRestShapeGivesAFlatStencil) {
    // The second triangle has zero area at the start (vertex 3 lies on the edge 0-1). The edge is
    // still shared by two triangles, and the contract gives such a stencil the rest angle pi (flat):
    // once the cloth moves the triangle opens, and the edge must resist bending like any other.
    const auto st = bendingStencils(kHingeTriangles, hinge(Vec3(0.5, 0, 0)));
    ASSERT_EQ(st.size(), 1u) << "the number of stencils of two triangles sharing one edge, one of them of zero area at the "
                                "start: the edge is interior all the same, so it gets its stencil";
    EXPECT_CLOSE(st[0].phi0, kPi, 1e-12) << "the rest angle phi0, in rad, of a stencil whose rest shape is not valid (a "
                                            "triangle of zero area): the header's contract for 5.3";
}

TEST(Task5_3_BendingStencils, FoldedClothStaysAtItsRestAngle) {
    // A 5 x 4 cloth folded by 60 degrees along its middle column.
    ClothSpec spec;
    spec.nx = 5, spec.ny = 4;
    State st = makeGridState(spec);
    for (int i = 0; i < st.size(); ++i) {
        const double u = st.x(0, i) - 0.5;  // column 2 is the fold line at x = 0.5
        if (u > 0) st.x.col(i) = Vec3(0.5 + u * std::cos(kPi / 3), st.x(1, i), u * std::sin(kPi / 3));
    }
    const auto tris = gridTriangles(spec.nx, spec.ny);
    const auto stencils = bendingStencils(tris, st.x);
    Matrix3X p = st.x;
    for (int it = 0; it < 20; ++it)
        for (const auto& s : stencils) {
            const auto c = projectBendingConstraint(p.col(s.i1), p.col(s.i2), p.col(s.i3), p.col(s.i4), 1, 1, 1, 1,
                                                    s.phi0, 1.0);
            p.col(s.i1) += c.dp1, p.col(s.i2) += c.dp2, p.col(s.i3) += c.dp3, p.col(s.i4) += c.dp4;
        }
    const double largestMove = (p - st.x).cwiseAbs().maxCoeff();
    EXPECT_LESS(largestMove, 1e-9) << "the largest coordinate change, in m, of a cloth folded at its rest angles after 20 sweeps of "
                                      "bending projections: a cloth at rest has nothing to correct, so it must not move";
    // Disturb it and project again: the bending error must shrink.
    Matrix3X q = st.x;
    q(2, 7) += 0.05, q(1, 12) -= 0.04, q(2, 18) -= 0.03;
    auto rms = [&](const Matrix3X& y) {
        double s2 = 0;
        for (const auto& s : stencils) {
            const double e = angleOf(y.col(s.i1), y.col(s.i2), y.col(s.i3), y.col(s.i4)) - s.phi0;
            s2 += e * e;
        }
        return std::sqrt(s2 / stencils.size());
    };
    const double before = rms(q);
    for (int it = 0; it < 20; ++it)
        for (const auto& s : stencils) {
            const auto c = projectBendingConstraint(q.col(s.i1), q.col(s.i2), q.col(s.i3), q.col(s.i4), 1, 1, 1, 1,
                                                    s.phi0, 0.5);
            q.col(s.i1) += c.dp1, q.col(s.i2) += c.dp2, q.col(s.i3) += c.dp3, q.col(s.i4) += c.dp4;
        }
    const double rmsAngleErrorAfter = rms(q);
    EXPECT_LESS(rmsAngleErrorAfter, 0.1 * before)
        << "the RMS angle error of the disturbed folded cloth in rad after 20 sweeps of bending projections (k = 0.5): the "
           "projections must bring it back to its rest shape, cutting the error by 90 % from " << before;
}

// ============================ Randomised property tests =======================================
// Random stencils, orientations, scales from 1 mm to 100 m and inverse masses; seeds 1..kPropertySeeds
// (test_util.h). Expected values from the independent dOf/angleOf above, finite differences and physics.

namespace {
using testing_util::forEachSeed;
using testing_util::RandomGeometry;

// A random stencil with dihedral angle phi: built in a frame with the edge p1-p2 along x, p3 at height h3
// above the edge in the x-y plane and p4 at height h4 rotated by phi about the edge (phi = pi: flat),
// then scaled by s, rotated and moved. h3 = sliver * (0.3 .. 1.5): sliver < 1 gives a thin triangle.
struct RandomStencil {
    Stencil st;
    double s = 1.0, phi = 0.0;
    RandomStencil(RandomGeometry& G, double sliver = 1.0) {
        s = G.scale();
        phi = G.uniform(0.3, kPi - 0.3);
        const double L = G.uniform(0.5, 1.5), h3 = sliver * G.uniform(0.3, 1.5), h4 = G.uniform(0.3, 1.5);
        const Vec3 local[4] = {Vec3::Zero(), Vec3(L, 0, 0), Vec3(G.uniform(-0.3, 1.3) * L, h3, 0),
                               Vec3(G.uniform(-0.3, 1.3) * L, h4 * std::cos(phi), h4 * std::sin(phi))};
        const Eigen::Matrix3d R = G.rotation();
        const Vec3 t = G.point(s);
        for (int i = 0; i < 4; ++i) st.p[i] = R * (s * local[i]) + t;
    }
    std::string describe() const {
        std::ostringstream o;
        o << "p1 = " << str(st.p[0]) << ", p2 = " << str(st.p[1]) << ", p3 = " << str(st.p[2]) << ", p4 = " << str(st.p[3])
          << " (size " << s << " m, dihedral angle " << phi << " rad)";
        return o.str();
    }
};

// The q-vectors against central differences of d with step h; empty string if they agree within tol.
std::string compareWithFiniteDifferences(const Stencil& s, const BendingGradients& g, double h, double tol) {
    const Vec3 q[4] = {g.q1, g.q2, g.q3, g.q4};
    for (int i = 0; i < 4; ++i)
        for (int a = 0; a < 3; ++a) {
            Stencil plus = s, minus = s;
            plus.p[i][a] += h, minus.p[i][a] -= h;
            const double fd =
                (dOf(plus.p[0], plus.p[1], plus.p[2], plus.p[3]) - dOf(minus.p[0], minus.p[1], minus.p[2], minus.p[3])) / (2 * h);
            if (!std::isfinite(q[i][a]) || std::abs(q[i][a] - fd) > tol) {
                std::ostringstream o;
                o << "q" << i + 1 << " = " << str(q[i]) << ": component " << a << " should be dd/dp = " << fd
                  << " (finite differences)";
                return o.str();
            }
        }
    return "";
}
}  // namespace

TEST(Task5_1_BendingGradients, RandomStencilsAtAnyScaleAndOrientation) {
    // d = cos(phi) and sin(phi) do not depend on the stencil's size, orientation or position; the q-vectors are
    // the gradients of d (finite differences), scale as 1/size, and sum to zero (moving all four points
    // together does not bend the stencil).
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const RandomStencil r(G);
        const Stencil& s = r.st;
        const auto g = bendingGradients(s.p[0], s.p[1], s.p[2], s.p[3]);
        if (!g.valid || std::abs(g.d - std::cos(r.phi)) > 1e-9 || std::abs(g.sinPhi - std::sin(r.phi)) > 1e-9)
            return testing::AssertionFailure() << "For a stencil of any size and orientation, d must be cos(phi) and sinPhi must be "
                                                  "sin(phi) of the dihedral angle phi = " << r.phi << " rad: got valid = " << g.valid
                                               << ", d = " << g.d << " (want " << std::cos(r.phi) << "), sinPhi = " << g.sinPhi
                                               << " (want " << std::sin(r.phi) << ") for " << r.describe()
                                               << ". An absolute area tolerance (m^2) fails for small stencils.";
        const std::string fd = compareWithFiniteDifferences(s, g, 1e-6 * r.s, 1e-5 / r.s);
        if (!fd.empty())
            return testing::AssertionFailure() << "The q-vectors must be the gradients dd/dp_i for a stencil of any size and "
                                                  "orientation: " << fd << "; " << r.describe() << ".";
        const Vec3 sum = g.q1 + g.q2 + g.q3 + g.q4;
        if (sum.norm() > 1e-9 / r.s)
            return testing::AssertionFailure() << "Moving all four points together does not bend the stencil, so q1 + q2 + q3 + q4 "
                                                  "must be zero; got " << str(sum) << " for " << r.describe() << ".";
        return testing::AssertionSuccess();
    });
}

TEST(Task5_1_BendingGradients, NearlyDegenerateTrianglesStillHaveGradients) {
    // A sliver: p3 only 1e-4 to 3e-2 of the edge length away from the edge line, at any size. The triangle
    // is thin but has an area (at least 1e-11 m^2 here), so it has a normal and d has a gradient.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const double sliver = G.logUniform(1e-4, 3e-2);
        const RandomStencil r(G, sliver);
        const Stencil& s = r.st;
        const auto g = bendingGradients(s.p[0], s.p[1], s.p[2], s.p[3]);
        const double area = (s.p[1] - s.p[0]).cross(s.p[2] - s.p[0]).norm();
        if (!g.valid)
            return testing::AssertionFailure() << "A thin triangle with the area " << area << " m^2 (above the 1e-12 m^2 of the task) "
                                                  "is valid and must give valid = true: " << r.describe()
                                               << ". An absolute area tolerance like 1e-6 m^2 rejects every triangle of a "
                                                  "millimetre-sized cloth.";
        const double qmax = std::max({g.q1.norm(), g.q2.norm(), g.q3.norm(), g.q4.norm()});
        const std::string fd = compareWithFiniteDifferences(s, g, 1e-4 * sliver * r.s, 1e-5 * qmax);
        if (!fd.empty())
            return testing::AssertionFailure() << "The q-vectors of a thin (but valid) triangle must still be the gradients of d: "
                                               << fd << "; " << r.describe() << ", p3 " << sliver << " edge lengths off the edge.";
        return testing::AssertionSuccess();
    });
}

TEST(Task5_2_ProjectBending, RandomStencilsMassesAndScales) {
    // A random stencil (any size and orientation) bent 0.01 to 0.03 rad away from its rest angle, random inverse
    // masses (ratios up to 1e4, sometimes one pinned). The projection is a Newton step on C: with a small
    // stiffness k it removes the fraction k of the error to first order (checked with k = 0.01), and with
    // k = 1 it reduces |C|. It keeps the momentum sum m_i dp_i and the angular momentum sum p_i x m_i dp_i at
    // zero, and does not move a pinned particle.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const RandomStencil r(G);
        const Stencil& s = r.st;
        double w[4];
        for (double& wi : w) wi = G.logUniform(1e-2, 1e2);
        const int pin = static_cast<int>(G.uniform(0.0, 8.0));  // 0..3: that particle pinned, else none
        if (pin < 4) w[pin] = 0.0;
        const double phi0 = r.phi + G.sign() * G.uniform(0.01, 0.03);
        std::ostringstream in;
        in << r.describe() << ", rest angle " << phi0 << " rad, w = (" << w[0] << ", " << w[1] << ", " << w[2] << ", " << w[3]
           << ") 1/kg";
        const double before = angleOf(s.p[0], s.p[1], s.p[2], s.p[3]) - phi0;
        const double k = 0.01;
        const auto small = projectBendingConstraint(s.p[0], s.p[1], s.p[2], s.p[3], w[0], w[1], w[2], w[3], phi0, k);
        const double removed = before - (angleAfter(s, small) - phi0);
        if (!(std::abs(removed - k * before) < 0.05 * k * std::abs(before)))
            return testing::AssertionFailure() << "The bending projection is a Newton step on C: with stiffness k = " << k
                                               << " it must remove the fraction k of the error (to first order), for any size, "
                                                  "orientation and masses; it removed " << removed << " rad of C = " << before
                                               << " rad instead of " << k * before << " rad, for " << in.str()
                                               << ". Check the weights w_j in sum w_j |q_j|^2.";
        const auto c = projectBendingConstraint(s.p[0], s.p[1], s.p[2], s.p[3], w[0], w[1], w[2], w[3], phi0, 1.0);
        const Vec3 dp[4] = {c.dp1, c.dp2, c.dp3, c.dp4};
        const double after = angleAfter(s, c) - phi0;
        if (!(std::abs(after) < std::abs(before)))
            return testing::AssertionFailure() << "One projection with k = 1 must reduce a small bending error, for any size, "
                                                  "orientation and masses: |C| went from " << std::abs(before) << " rad to "
                                               << std::abs(after) << " rad for " << in.str() << ".";
        Vec3 P = Vec3::Zero(), L = Vec3::Zero();
        double scale = 0.0;
        for (int i = 0; i < 4; ++i) {
            if (w[i] == 0.0) {
                if (dp[i].norm() != 0.0)
                    return testing::AssertionFailure() << "A pinned particle (w = 0) must not move; p" << i + 1 << " moved by "
                                                       << str(dp[i]) << " for " << in.str() << ".";
                continue;
            }
            P += dp[i] / w[i], L += s.p[i].cross(dp[i]) / w[i], scale += dp[i].norm() / w[i];
        }
        if (pin >= 4 && (P.norm() > 1e-9 * scale || L.norm() > 1e-9 * scale * (r.s + s.p[0].norm())))
            return testing::AssertionFailure() << "The bending projection is internal: it must create no momentum (sum m_i dp_i = "
                                               << str(P) << ") and no angular momentum (sum p_i x m_i dp_i = " << str(L)
                                               << "), for " << in.str() << ".";
        return testing::AssertionSuccess();
    });
}

// ================================ Experiment (answers.json) ===================================
// The stage's experiment (task sheet, "Experiment"): predict from theory, measure with your own code,
// explain the difference, in exercises/05_bending/answers.json. This test checks only that the file is
// complete and well formed; the numbers are graded by the instructor.
TEST(Experiments, AnswerFileIsComplete) {
    EXPECT_TRUE(testing_util::answerFileIsComplete("05_bending", {"bending_error_stiffness_0_1", "bending_error_stiffness_0_5"}, {"bending_error_stiffness_0_1", "bending_error_stiffness_0_5"}));
}
