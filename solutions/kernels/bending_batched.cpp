// The batched bending sweep (solver.bending_kernel "batched"); formulas in bending_batched.h.
//
// How it is made fast, for the curious (none of this is needed for the exercises):
// - one `#pragma omp simd` loop over a block of stencils that share no particle: the compiler may
//   then run 8 stencils at once in AVX-512 registers, loading and storing p with gather/scatter;
// - `target_clones`: the compiler builds the sweep for plain x86-64, for AVX2 (x86-64-v3) and for
//   AVX-512 (x86-64-v4), and the program picks the best one the CPU has when it starts;
// - no branches in the loop body: every case is computed and the result selected (`c ? x : y` on
//   doubles), and the angle is a polynomial instead of std::acos (a library call the loop cannot
//   vectorise);
// - the file is compiled with -fno-math-errno (sqrt may become one instruction) and
//   -fno-trapping-math (see framework/CMakeLists.txt); results are plain IEEE double arithmetic.
#include "bending_batched.h"

#include <algorithm>
#include <cmath>

namespace clothlab {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kTanPi8 = 0.41421356237309504880;  // tan(π/8) = √2 − 1
constexpr int kAtanTerms = 20;

// c_n = (−1)^n / (2n + 1), the Taylor coefficients of arctan, computed by the compiler.
struct AtanCoefficients {
    double c[kAtanTerms] = {};
    constexpr AtanCoefficients() {
        for (int n = 0; n < kAtanTerms; ++n) c[n] = (n % 2 ? -1.0 : 1.0) / (2 * n + 1);
    }
};
constexpr AtanCoefficients kAtan;

// atan2(y, x) for y >= 0, one division, no branch (see atan2Upper()).
[[gnu::always_inline]] inline double angleUpper(double y, double x) {
    const double ax = std::fabs(x);
    const double mn = y < ax ? y : ax, mx = y < ax ? ax : y;  // angle of (mx, mn) is in [0, π/4]
    const bool far = mn > kTanPi8 * mx;                        // in (π/8, π/4]: shift by π/4
    const double t = (far ? mn - mx : mn) / (far ? mn + mx : mx);  // |t| <= tan(π/8)
    const double t2 = t * t;
    double poly = kAtan.c[kAtanTerms - 1];
#pragma GCC unroll 20
    for (int n = kAtanTerms - 2; n >= 0; --n) poly = poly * t2 + kAtan.c[n];
    double angle = (far ? 0.25 * kPi : 0.0) + t * poly;
    angle = y > ax ? 0.5 * kPi - angle : angle;  // undo the swap of x and y
    return x < 0.0 ? kPi - angle : angle;        // undo the mirror at the y axis
}

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define CLOTHLAB_VECTOR_CLONES __attribute__((target_clones("default", "arch=x86-64-v3", "arch=x86-64-v4")))
#else
#define CLOTHLAB_VECTOR_CLONES
#endif

// The sweep on raw arrays: P is p's storage (x, y, z of particle i at P[3i], P[3i+1], P[3i+2]).
CLOTHLAB_VECTOR_CLONES
void sweep(const BendingBlocks& B, const double* w, double k, double* P) {
    const int* I1 = B.i1.data();
    const int* I2 = B.i2.data();
    const int* I3 = B.i3.data();
    const int* I4 = B.i4.data();
    const double* phi0 = B.phi0.data();
    const int blocks = static_cast<int>(B.start.size()) - 1;
    for (int blk = 0; blk < blocks; ++blk) {
        const int first = B.start[blk], last = B.start[blk + 1];
#pragma omp simd
        for (int s = first; s < last; ++s) {
            const int i1 = 3 * I1[s], i2 = 3 * I2[s], i3 = 3 * I3[s], i4 = 3 * I4[s];
            // a, b, c: p2, p3, p4 relative to p1
            const double ax = P[i2] - P[i1], ay = P[i2 + 1] - P[i1 + 1], az = P[i2 + 2] - P[i1 + 2];
            const double bx = P[i3] - P[i1], by = P[i3 + 1] - P[i1 + 1], bz = P[i3 + 2] - P[i1 + 2];
            const double cx = P[i4] - P[i1], cy = P[i4 + 1] - P[i1 + 1], cz = P[i4 + 2] - P[i1 + 2];
            // m1 = a x b, m2 = a x c
            const double m1x = ay * bz - az * by, m1y = az * bx - ax * bz, m1z = ax * by - ay * bx;
            const double m2x = ay * cz - az * cy, m2y = az * cx - ax * cz, m2z = ax * cy - ay * cx;
            const double L1 = m1x * m1x + m1y * m1y + m1z * m1z;
            const double L2 = m2x * m2x + m2y * m2y + m2z * m2z;
            const double D = m1x * m2x + m1y * m2y + m1z * m2z;
            // S = |m1 x m2| = |a.(b x c)| |a|
            const double vol = ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
            const double S2 = vol * vol * (ax * ax + ay * ay + az * az);
            const double S = std::sqrt(S2);
            const double phi = angleUpper(S, D);
            // E1 = L1 m2 − D m1, E2 = L2 m1 − D m2
            const double e1x = L1 * m2x - D * m1x, e1y = L1 * m2y - D * m1y, e1z = L1 * m2z - D * m1z;
            const double e2x = L2 * m1x - D * m2x, e2y = L2 * m1y - D * m2y, e2z = L2 * m1z - D * m2z;
            // Q3 = L2 E1 x a, Q4 = L1 E2 x a, Q2 = L2 b x E1 + L1 c x E2, Q1 = −Q2 − Q3 − Q4
            const double q3x = L2 * (e1y * az - e1z * ay), q3y = L2 * (e1z * ax - e1x * az), q3z = L2 * (e1x * ay - e1y * ax);
            const double q4x = L1 * (e2y * az - e2z * ay), q4y = L1 * (e2z * ax - e2x * az), q4z = L1 * (e2x * ay - e2y * ax);
            const double q2x = L2 * (by * e1z - bz * e1y) + L1 * (cy * e2z - cz * e2y);
            const double q2y = L2 * (bz * e1x - bx * e1z) + L1 * (cz * e2x - cx * e2z);
            const double q2z = L2 * (bx * e1y - by * e1x) + L1 * (cx * e2y - cy * e2x);
            const double q1x = -q2x - q3x - q4x, q1y = -q2y - q3y - q4y, q1z = -q2z - q3z - q4z;
            const double w1 = w[I1[s]], w2 = w[I2[s]], w3 = w[I3[s]], w4 = w[I4[s]];
            const double Dn = w1 * (q1x * q1x + q1y * q1y + q1z * q1z) + w2 * (q2x * q2x + q2y * q2y + q2z * q2z) +
                              w3 * (q3x * q3x + q3y * q3y + q3z * q3z) + w4 * (q4x * q4x + q4y * q4y + q4z * q4z);
            const double LL = L1 * L2;
            double f = k * (phi - phi0[s]) * LL * S / Dn;
            // The cases without a correction (as in exercise 5.2), as selects, not branches.
            f = L1 < 1e-24 ? 0.0 : f;              // zero-area triangle
            f = L2 < 1e-24 ? 0.0 : f;
            f = S2 < 1e-12 * LL ? 0.0 : f;         // flat or folded: 1 − d² < 1e-12
            f = Dn < 1e-24 * LL * LL * LL ? 0.0 : f;  // all pinned: Σ w_j |q_j|² < 1e-24
            const double f1 = f * w1, f2 = f * w2, f3 = f * w3, f4 = f * w4;
            P[i1] += f1 * q1x, P[i1 + 1] += f1 * q1y, P[i1 + 2] += f1 * q1z;
            P[i2] += f2 * q2x, P[i2 + 1] += f2 * q2y, P[i2 + 2] += f2 * q2z;
            P[i3] += f3 * q3x, P[i3 + 1] += f3 * q3y, P[i3 + 2] += f3 * q3z;
            P[i4] += f4 * q4x, P[i4 + 1] += f4 * q4y, P[i4 + 2] += f4 * q4z;
        }
    }
}
}  // namespace

double atan2Upper(double y, double x) { return angleUpper(y, x); }

BendingBlocks bendingBlocks(const std::vector<BendingStencil>& stencils) {
    BendingBlocks B;
    int maxIndex = -1;
    for (const BendingStencil& s : stencils) maxIndex = std::max({maxIndex, s.i1, s.i2, s.i3, s.i4});
    std::vector<int> blockOf(static_cast<size_t>(maxIndex + 1), -1);  // last block a particle is in
    for (const BendingStencil& s : stencils) {
        const int current = static_cast<int>(B.start.size()) - 1;
        const int ids[4] = {s.i1, s.i2, s.i3, s.i4};
        bool shares = false;
        for (int i : ids) shares = shares || blockOf[static_cast<size_t>(i)] == current;
        const int size = current < 0 ? 0 : static_cast<int>(B.i1.size()) - B.start.back();
        if (current < 0 || shares || size == kBendingBlockSize) B.start.push_back(static_cast<int>(B.i1.size()));
        for (int i : ids) blockOf[static_cast<size_t>(i)] = static_cast<int>(B.start.size()) - 1;
        B.i1.push_back(s.i1);
        B.i2.push_back(s.i2);
        B.i3.push_back(s.i3);
        B.i4.push_back(s.i4);
        B.phi0.push_back(s.phi0);
    }
    B.start.push_back(static_cast<int>(B.i1.size()));
    return B;
}

void projectBendingBlocks(const BendingBlocks& blocks, const VectorX& w, double k, Matrix3X& p) {
    sweep(blocks, w.data(), k, p.data());
}

}  // namespace clothlab
