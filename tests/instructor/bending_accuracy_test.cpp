// Accuracy of the stage-05 reference (exercise 5.2, projectBendingConstraint) near flat, against the
// same formulas evaluated in long double. In tests/instructor/ because the long-double version spells
// out the solution of stage 05.
//
// Why: near flat, d = n1·n2 → −1 and the textbook sin φ = sqrt(1 − d²) cancels (1 − d² has a relative
// error of about ε/(1 − d²)), while sin φ = |n1 × n2| is computed directly (relative error about
// ε/sin φ). Far from the rest angle the correction is large (|Δp| ≈ |C| × the triangle's height, some
// 0.1 m on 1 m stencils), so the lost digits show up in metres. The test measures the reference and,
// for comparison, the textbook form in double, on random nearly flat stencils of about 1 m.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>

#include "clothlab/exercise/05_bending.h"

using namespace clothlab;

namespace {

using LD = long double;
using VL = Eigen::Matrix<long double, 3, 1>;
using Corr = std::array<Vec3, 4>;

struct Sample {
    Vec3 p[4];
    double w[4];
    double phi0;
    double theta;  // π − φ of the construction, rad
};

// Exercise 5.2's formulas in any floating-point type T, in one of two forms. The header's (sound)
// form: sin φ = |n1 × n2|, φ = atan2(sin φ, d), no correction for sin φ < 1e-6. The textbook form of
// Müller et al. 2007 (and of this course's first header): sin φ = sqrt(1 − d²), φ = arccos d, no
// correction for 1 − d² < 1e-12. Returns false where the form gives no correction.
template <typename T>
bool projection(const Sample& s, double k, bool textbookForm, std::array<Eigen::Matrix<T, 3, 1>, 4>& dp) {
    using V = Eigen::Matrix<T, 3, 1>;
    const V p2 = s.p[1].cast<T>() - s.p[0].cast<T>(), p3 = s.p[2].cast<T>() - s.p[0].cast<T>(),
            p4 = s.p[3].cast<T>() - s.p[0].cast<T>();
    const T A1 = p2.cross(p3).norm(), A2 = p2.cross(p4).norm();
    if (A1 < T(1e-12) || A2 < T(1e-12)) return false;
    const V n1 = p2.cross(p3) / A1, n2 = p2.cross(p4) / A2;
    const T d = std::clamp(n1.dot(n2), T(-1), T(1));
    if (textbookForm ? 1 - d * d < T(1e-12) : n1.cross(n2).norm() < T(1e-6)) return false;
    const T sinPhi = textbookForm ? std::sqrt(1 - d * d) : n1.cross(n2).norm();
    const T phi = textbookForm ? std::acos(d) : std::atan2(sinPhi, d);
    V q[4];
    q[2] = (n2.cross(p2) + p2.cross(n1) * d) / A1;
    q[3] = (n1.cross(p2) + p2.cross(n2) * d) / A2;
    q[1] = (p3.cross(n2) + n1.cross(p3) * d) / A1 + (p4.cross(n1) + n2.cross(p4) * d) / A2;
    q[0] = -q[1] - q[2] - q[3];
    T sum = 0;
    for (int i = 0; i < 4; ++i) sum += T(s.w[i]) * q[i].squaredNorm();
    if (sum < T(1e-24)) return false;
    const T scale = T(k) * sinPhi * (phi - T(s.phi0)) / sum;
    for (int i = 0; i < 4; ++i) dp[i] = scale * T(s.w[i]) * q[i];
    return true;
}
// The header's form in long double: the truth.
bool truthLongDouble(const Sample& s, double k, std::array<VL, 4>& dp) { return projection<LD>(s, k, false, dp); }
// The textbook form.
template <typename T>
bool textbook(const Sample& s, double k, std::array<Eigen::Matrix<T, 3, 1>, 4>& dp) { return projection<T>(s, k, true, dp); }

// A random stencil of about 1 m, rotated arbitrarily, bent by θ from flat (φ = π − θ).
// far: rest angle π − 0.5 (a crease pressed flat); else a rest angle near φ (|C| ≈ θ/2 or less).
Sample randomStencil(std::mt19937& rng, double theta, bool far) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    VL e(u(rng), u(rng), u(rng));
    e.normalize();
    VL a = e.unitOrthogonal();
    const LD turn = LD(M_PI) * u(rng);
    a = std::cos(turn) * a + std::sin(turn) * e.cross(a);  // a random direction perpendicular to the edge
    const VL b = e.cross(a);
    const LD len = 1.0L + 0.3L * u(rng), h3 = 0.75L + 0.25L * u(rng), h4 = 0.75L + 0.25L * u(rng);
    const LD t3 = len * (0.5L + 0.3L * u(rng)), t4 = len * (0.5L + 0.3L * u(rng));
    const LD th = u(rng) < 0 ? -LD(theta) : LD(theta);  // either way out of the plane
    const VL o(0.3L * u(rng), 0.3L * u(rng), 0.3L * u(rng));
    Sample s;
    s.p[0] = o.cast<double>();
    s.p[1] = (o + len * e).cast<double>();
    s.p[2] = (o + t3 * e + h3 * a).cast<double>();
    s.p[3] = (o + t4 * e + h4 * (-std::cos(th) * a + std::sin(th) * b)).cast<double>();
    for (double& w : s.w) w = std::pow(10.0, u(rng));
    s.theta = theta;
    s.phi0 = far ? M_PI - 0.5 : M_PI - theta * (1.0 + 0.5 * u(rng));
    return s;
}

double largestDifference(const Corr& c, const std::array<VL, 4>& truth) {
    double e = 0;
    for (int i = 0; i < 4; ++i) e = std::max(e, static_cast<double>((c[i].cast<LD>() - truth[i]).norm()));
    return e;
}

}  // namespace

TEST(BendingAccuracy, ReferenceAgreesWithLongDoubleNearFlat) {
    // θ = π − φ per decade, log-uniform; the first line just above the cut-off sin φ = 1e-6.
    const double decades[][2] = {{1.001e-6, 1.1e-6}, {1.1e-6, 1e-5}, {1e-5, 1e-4},
                                 {1e-4, 1e-3},       {1e-3, 1e-2},   {1e-2, 1e-1}};
    std::mt19937 rng(2007);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    double worstRef = 0, worstTextbook = 0, worstTextbookFrom1e4 = 0, largestDp = 0, worstTextbookLD = 0;
    int textbookCutOff = 0;  // stencils above the cut-off that the textbook form takes for flat (1 − d² < 1e-12)
    std::printf("largest |Δp − Δp(long double)|, m, on 4000 random stencils of about 1 m per line\n");
    std::printf("%-22s %-6s %12s %12s %12s\n", "θ = π − φ, rad", "φ0", "reference", "textbook", "largest |Δp|");
    for (const auto& dec : decades)
        for (bool far : {true, false}) {
            double ref = 0, tb = 0, big = 0;
            for (int t = 0; t < 4000; ++t) {
                const double theta = dec[0] * std::pow(dec[1] / dec[0], u01(rng));
                const Sample s = randomStencil(rng, theta, far);
                std::array<VL, 4> truth;
                const bool moves = truthLongDouble(s, 1.0, truth);
                ASSERT_TRUE(moves) << "θ = " << theta << " is above the cut-off: the stencil must be corrected";
                const BendingCorrection r =
                    projectBendingConstraint(s.p[0], s.p[1], s.p[2], s.p[3], s.w[0], s.w[1], s.w[2], s.w[3], s.phi0, 1.0);
                ref = std::max(ref, largestDifference({r.dp1, r.dp2, r.dp3, r.dp4}, truth));
                for (const auto& v : truth) big = std::max(big, static_cast<double>(v.norm()));
                std::array<Vec3, 4> old;
                if (textbook<double>(s, 1.0, old))
                    tb = std::max(tb, largestDifference(old, truth));
                else
                    ++textbookCutOff;
                std::array<VL, 4> oldLD;
                if (theta >= 1e-3 && textbook<LD>(s, 1.0, oldLD)) {  // the same formula, only less accurate
                    Corr c;
                    for (int i = 0; i < 4; ++i) c[i] = oldLD[i].cast<double>();
                    worstTextbookLD = std::max(worstTextbookLD, largestDifference(c, truth));
                }
            }
            std::printf("[%.3e, %.1e)  %-6s %12.2e %12.2e %12.2e\n", dec[0], dec[1], far ? "π−0.5" : "≈φ", ref, tb,
                        big);
            worstRef = std::max(worstRef, ref);
            worstTextbook = std::max(worstTextbook, tb);
            if (dec[0] >= 1e-4) worstTextbookFrom1e4 = std::max(worstTextbookFrom1e4, tb);
            largestDp = std::max(largestDp, big);
        }
    std::printf("reference %.2e m, textbook form (sqrt(1 − d²), acos d) %.2e m (%.2e m for θ ≥ 1e-4); the textbook\n"
                "form took %d of these stencils for flat (1 − d² < 1e-12, no correction; not counted above)\n",
                worstRef, worstTextbook, worstTextbookFrom1e4, textbookCutOff);
    EXPECT_GT(largestDp, 0.1) << "far from the rest angle the corrections must be large (where the error shows)";
    EXPECT_LE(worstTextbookLD, 1e-12) << "in long double, the textbook form and the truth agree for θ ≥ 1e-3";
    EXPECT_LE(worstRef, 1e-9) << "largest error of the reference near flat, m (stencils of about 1 m)";
    // The bound above is one the textbook form cannot meet: this test can fail.
    EXPECT_GT(worstTextbook, 1e-9) << "the textbook form sqrt(1 − d²) should lose digits near flat";
}

TEST(BendingAccuracy, ReferenceAgreesWithLongDoubleAtAnyAngle) {
    // Away from flat the two forms agree; the reference must be accurate on the whole range of φ.
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    double worst = 0;
    for (int t = 0; t < 20000; ++t) {
        const double theta = 1e-2 + (M_PI - 2e-2) * u01(rng);  // φ from 0.01 to π − 0.01
        const Sample s = randomStencil(rng, theta, t % 2 == 0);
        std::array<VL, 4> truth;
        ASSERT_TRUE(truthLongDouble(s, 0.7, truth));
        const BendingCorrection r =
            projectBendingConstraint(s.p[0], s.p[1], s.p[2], s.p[3], s.w[0], s.w[1], s.w[2], s.w[3], s.phi0, 0.7);
        worst = std::max(worst, largestDifference({r.dp1, r.dp2, r.dp3, r.dp4}, truth));
    }
    std::printf("reference against long double, φ in [0.01, π − 0.01]: %.2e m\n", worst);
    EXPECT_LE(worst, 1e-12);
}
