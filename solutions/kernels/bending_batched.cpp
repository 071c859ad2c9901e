// The batched bending sweep (solver.kernel "batched"); formulas in bending_batched.h.
//
// How it is made fast, for the curious (none of this is needed for the exercises):
// - the stencils of a block share no particle, so `#pragma omp simd` may run them side by side:
//   8 at once in AVX-512 registers, 4 with AVX2, 2 in WebAssembly's 128-bit vectors (./lab web);
// - with AVX-512 (sweepDirect) the vector loop loads and stores p itself, with gather and scatter
//   instructions; without (sweepStaged: AVX2 has no scatter) the vector loop writes the corrections
//   to an array, and a plain loop adds them to p;
// - with GCC 12 on x86-64 Linux, `target_clones` builds each sweep for AVX-512 or AVX2 and for
//   plain x86-64, and projectBendingBlocks() picks what the CPU has (elsewhere: one plain build);
// - no branches in bendingCorrection(): every case is computed and the result selected
//   (`c ? x : y` on doubles), and the angle is a polynomial instead of std::acos (a library call
//   the loop cannot vectorise);
// - the file is compiled with -fno-math-errno (sqrt may become one instruction) and
//   -fno-trapping-math (see cmake/extensions.cmake); results are IEEE double arithmetic, with
//   fused multiply-adds where the CPU has them, so the last digits depend on the CPU.
#include "bending_batched.h"

#include <algorithm>
#include <cmath>

namespace clothlab {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kTanPi16 = 0.19891236737965800691;   // tan(π/16) = √(4 + 2√2) − √2 − 1
constexpr double kTanPi8 = 0.41421356237309504880;    // tan(π/8) = √2 − 1
constexpr double kTan3Pi16 = 0.66817863791929891999;  // tan(3π/16) = √(4 − 2√2) − √2 + 1
constexpr int kAtanTerms = 12;  // |t| <= tan(π/16): truncation error below t²⁵/25 < 1e-19

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
    const double mn = y < ax ? y : ax, mx = y < ax ? ax : y;  // angle θ of (mx, mn) is in [0, π/4]
    // θ − σ for the nearest σ of 0, π/8, π/4: tan(θ − σ) = (mn − mx tan σ) / (mx + mn tan σ)
    const bool past1 = mn > kTanPi16 * mx, past3 = mn > kTan3Pi16 * mx;  // θ > π/16, θ > 3π/16
    const double tanSigma = past3 ? 1.0 : past1 ? kTanPi8 : 0.0;
    const double t = (mn - mx * tanSigma) / (mx + mn * tanSigma);  // |t| <= tan(π/16)
    // Σ c_n t2ⁿ as four Horner chains in t2⁴ (chain r: c_r, c_{r+4}, ...): the same polynomial, but
    // four independent multiply-add chains instead of one, which a vector loop would wait on.
    const double t2 = t * t, t4 = t2 * t2, t8 = t4 * t4;
    static_assert(kAtanTerms % 4 == 0, "four chains of equal length");
    double q[4];
#pragma GCC unroll 4
    for (int r = 0; r < 4; ++r) {
        q[r] = kAtan.c[kAtanTerms - 4 + r];
#pragma GCC unroll 3
        for (int n = kAtanTerms - 8 + r; n >= 0; n -= 4) q[r] = q[r] * t8 + kAtan.c[n];
    }
    const double poly = (q[0] + t2 * q[1]) + t4 * (q[2] + t2 * q[3]);
    double angle = (past3 ? 0.25 * kPi : past1 ? 0.125 * kPi : 0.0) + t * poly;
    angle = y > ax ? 0.5 * kPi - angle : angle;  // undo the swap of x and y
    return x < 0.0 ? kPi - angle : angle;        // undo the mirror at the y axis
}

// One stencil's corrections Δp1..Δp4 of p1..p4 with inverse masses w[j1..j4] (formulas in
// bending_batched.h), without branches so that a loop over stencils can run it in vector
// registers. (Plain doubles in and out: GCC 12 vectorises that better than small arrays.)
[[gnu::always_inline]] inline void bendingCorrection(
    double p1x, double p1y, double p1z, double p2x, double p2y, double p2z,
    double p3x, double p3y, double p3z, double p4x, double p4y, double p4z,
    const double* w, int j1, int j2, int j3, int j4, double phi0, double k, double alphaTilde, double lambda,
    double& dLambda, double& d1x, double& d1y, double& d1z, double& d2x, double& d2y, double& d2z,
    double& d3x, double& d3y, double& d3z, double& d4x, double& d4y, double& d4z) {
    // a, b, c: p2, p3, p4 relative to p1
    const double ax = p2x - p1x, ay = p2y - p1y, az = p2z - p1z;
    const double bx = p3x - p1x, by = p3y - p1y, bz = p3z - p1z;
    const double cx = p4x - p1x, cy = p4y - p1y, cz = p4z - p1z;
    // m1 = a x b, m2 = a x c
    const double m1x = ay * bz - az * by, m1y = az * bx - ax * bz, m1z = ax * by - ay * bx;
    const double m2x = ay * cz - az * cy, m2y = az * cx - ax * cz, m2z = ax * cy - ay * cx;
    const double L1 = m1x * m1x + m1y * m1y + m1z * m1z;
    const double L2 = m2x * m2x + m2y * m2y + m2z * m2z;
    const double D = m1x * m2x + m1y * m2y + m1z * m2z;
    // S = |m1 x m2| = |a.(b x c)| |a|
    const double A = ax * ax + ay * ay + az * az, ab = ax * bx + ay * by + az * bz, ac = ax * cx + ay * cy + az * cz;
    const double vol = m1x * cx + m1y * cy + m1z * cz;  // a.(b x c) = (a x b).c
    const double la = std::sqrt(A);
    const double S = std::fabs(vol) * la, S2 = vol * vol * A;
    const double phi = angleUpper(S, D);
    // G_j = ∇_j φ · L1 L2 |a| · sign(vol): G3 = −A L2 m1, G4 = A L1 m2, G1 = (A − a·b) L2 m1 − (A − a·c) L1 m2,
    // G2 = (a·b) L2 m1 − (a·c) L1 m2 (bending_batched.h)
    const double u1x = L2 * m1x, u1y = L2 * m1y, u1z = L2 * m1z;  // L2 m1
    const double u2x = L1 * m2x, u2y = L1 * m2y, u2z = L1 * m2z;  // L1 m2
    const double q3x = -A * u1x, q3y = -A * u1y, q3z = -A * u1z;
    const double q4x = A * u2x, q4y = A * u2y, q4z = A * u2z;
    const double q2x = ab * u1x - ac * u2x, q2y = ab * u1y - ac * u2y, q2z = ab * u1z - ac * u2z;
    const double q1x = -q2x - q3x - q4x, q1y = -q2y - q3y - q4y, q1z = -q2z - q3z - q4z;
    const double w1 = w[j1], w2 = w[j2], w3 = w[j3], w4 = w[j4];  // loaded late: fewer live registers
    const double Dn = w1 * (q1x * q1x + q1y * q1y + q1z * q1z) + w2 * (q2x * q2x + q2y * q2y + q2z * q2z) +
                      w3 * (q3x * q3x + q3y * q3y + q3z * q3z) + w4 * (q4x * q4x + q4y * q4y + q4z * q4z);
    const double LL = L1 * L2;
    // σ = L1 L2 |a|, the G's scale. PBD (α̃ = 0): f = −sign(vol) k C σ/Σw|G|²; XPBD (k = 1):
    // f = −sign(vol) (C + α̃λ) σ/(Σw|G|² + α̃σ²), Δλ = sign(vol) f σ; then Δp_j = f w_j G_j.
    const double sigma = LL * la, sign = std::copysign(1.0, vol);
    double f = -sign * (k * (phi - phi0) + alphaTilde * lambda) * sigma / (Dn + alphaTilde * sigma * sigma);
    // The cases without a correction (as in exercise 5.2), as selects, not branches.
    f = L1 < 1e-24 ? 0.0 : f;                      // zero-area triangle
    f = L2 < 1e-24 ? 0.0 : f;
    f = S2 < 1e-12 * LL ? 0.0 : f;                 // flat or folded: sin²φ = S²/(L1 L2) < 1e-12
    f = S2 * Dn < 1e-24 * LL * LL * LL * A ? 0.0 : f;  // all pinned: Σ w_j |q_j|² = sin²φ Σw|G|²/σ² < 1e-24
    dLambda = sign * f * sigma;
    const double f1 = f * w1, f2 = f * w2, f3 = f * w3, f4 = f * w4;
    d1x = f1 * q1x, d1y = f1 * q1y, d1z = f1 * q1z;
    d2x = f2 * q2x, d2y = f2 * q2y, d2z = f2 * q2z;
    d3x = f3 * q3x, d3y = f3 * q3y, d3z = f3 * q3z;
    d4x = f4 * q4x, d4y = f4 * q4y, d4z = f4 * q4z;
}

// Blocks firstBlock .. lastBlock − 1 of BendingBlocks as plain pointers, for the sweeps' loops.
struct BlockArrays {
    const int *i1, *i2, *i3, *i4;  // particles of each stencil
    const double* phi0;            // rest angle of each stencil
    const int* start;              // block b: stencils start[b] .. start[b+1] − 1
    int first, last;               // the blocks to sweep
    double* lambda;                // XPBD: λ of each stencil (updated); PBD: null
    BlockArrays(const BendingBlocks& B, int firstBlock, int lastBlock, double* lambdas)
        : i1(B.i1.data()), i2(B.i2.data()), i3(B.i3.data()), i4(B.i4.data()), phi0(B.phi0.data()),
          start(B.start.data()), first(firstBlock), last(lastBlock), lambda(lambdas) {}
};

// target_clones with "arch=x86-64-vN" needs GCC 12 and ifunc (glibc); elsewhere one plain build.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12 && defined(__x86_64__) && defined(__GLIBC__)
#define CLOTHLAB_X86_DISPATCH 1
#endif

// The sweep with AVX-512: one vector loop per block that gathers p from and scatters it back to
// P = p's storage (x, y, z of particle i at P[3i], P[3i + 1], P[3i + 2]). `omp simd` tells the
// compiler what it cannot prove: the stencils of a block share no particle, so the iterations do
// not depend on each other.
#ifdef CLOTHLAB_X86_DISPATCH
__attribute__((target_clones("default", "arch=x86-64-v4")))
#endif
void sweepDirect(const BlockArrays& B, const double* w, double k, double alphaTilde, double* P) {
    const int *I1 = B.i1, *I2 = B.i2, *I3 = B.i3, *I4 = B.i4;
    alignas(64) double unused[kBendingBlockSize];  // PBD: λ = 0 for every stencil of a block
    for (int blk = B.first; blk < B.last; ++blk) {
        const int first = B.start[blk], n = B.start[blk + 1] - first;
        double* lam = B.lambda ? B.lambda + first : unused;
        if (!B.lambda) std::fill(unused, unused + kBendingBlockSize, 0.0);
#pragma omp simd
        for (int l = 0; l < n; ++l) {
            const int s = first + l, i1 = 3 * I1[s], i2 = 3 * I2[s], i3 = 3 * I3[s], i4 = 3 * I4[s];
            double dl, d1x, d1y, d1z, d2x, d2y, d2z, d3x, d3y, d3z, d4x, d4y, d4z;
            bendingCorrection(P[i1], P[i1 + 1], P[i1 + 2], P[i2], P[i2 + 1], P[i2 + 2], P[i3], P[i3 + 1], P[i3 + 2],
                              P[i4], P[i4 + 1], P[i4 + 2], w, I1[s], I2[s], I3[s], I4[s], B.phi0[s], k, alphaTilde,
                              lam[l], dl, d1x, d1y, d1z, d2x, d2y, d2z, d3x, d3y, d3z, d4x, d4y, d4z);
            lam[l] += dl;
            P[i1] += d1x, P[i1 + 1] += d1y, P[i1 + 2] += d1z;
            P[i2] += d2x, P[i2 + 1] += d2y, P[i2 + 2] += d2z;
            P[i3] += d3x, P[i3 + 1] += d3y, P[i3 + 2] += d3z;
            P[i4] += d4x, P[i4 + 1] += d4y, P[i4 + 2] += d4z;
        }
    }
}

// The sweep without scatter instructions (AVX2 has none, plain x86-64 neither): per block, one
// vector loop loads p (AVX2 has gather) and computes the corrections into the array Dp
// (Dp[3j + c][l]: coordinate c of Δp_j of the block's stencil l); then they are added to p one
// stencil at a time.
#ifdef CLOTHLAB_X86_DISPATCH
__attribute__((target_clones("default", "arch=x86-64-v3")))
#endif
void sweepStaged(const BlockArrays& B, const double* w, double k, double alphaTilde, double* P) {
    const int *I1 = B.i1, *I2 = B.i2, *I3 = B.i3, *I4 = B.i4;
    alignas(64) double Dp[12][kBendingBlockSize];
    alignas(64) double unused[kBendingBlockSize];  // PBD: λ = 0 for every stencil of a block
    for (int blk = B.first; blk < B.last; ++blk) {
        const int first = B.start[blk], n = B.start[blk + 1] - first;
        double* lam = B.lambda ? B.lambda + first : unused;
        if (!B.lambda) std::fill(unused, unused + kBendingBlockSize, 0.0);
#pragma omp simd
        for (int l = 0; l < n; ++l) {
            const int s = first + l, i1 = 3 * I1[s], i2 = 3 * I2[s], i3 = 3 * I3[s], i4 = 3 * I4[s];
            double dl;
            bendingCorrection(P[i1], P[i1 + 1], P[i1 + 2], P[i2], P[i2 + 1], P[i2 + 2], P[i3], P[i3 + 1], P[i3 + 2],
                              P[i4], P[i4 + 1], P[i4 + 2], w, I1[s], I2[s], I3[s], I4[s], B.phi0[s], k, alphaTilde,
                              lam[l], dl, Dp[0][l], Dp[1][l], Dp[2][l], Dp[3][l], Dp[4][l], Dp[5][l], Dp[6][l], Dp[7][l],
                              Dp[8][l], Dp[9][l], Dp[10][l], Dp[11][l]);
            lam[l] += dl;
        }
        for (int l = 0; l < n; ++l) {
            const int s = first + l;
            const int id[4] = {I1[s], I2[s], I3[s], I4[s]};
            for (int j = 0; j < 4; ++j)
                for (int c = 0; c < 3; ++c) P[3 * id[j] + c] += Dp[3 * j + c][l];
        }
    }
}
// Both sweeps, colour group by colour group (forEachGroupShare()): PBD (α̃ = 0, lambda null) or XPBD (k = 1).
void sweepBlocks(const BendingBlocks& blocks, const VectorX& w, double k, double alphaTilde, double* lambda, Matrix3X& p,
                 BendingLoop loop) {
    const auto sweep = loop == BendingLoop::Best && bendingBlocksUseScatter() ? sweepDirect : sweepStaged;
    forEachGroupShare(blocks.groups, blocks.threads, kParallelGroup / kBendingBlockSize, [&](int begin, int end) {
        sweep(BlockArrays(blocks, begin, end, lambda), w.data(), k, alphaTilde, p.data());
    });
}
}  // namespace

double atan2Upper(double y, double x) { return angleUpper(y, x); }

BendingBlocks bendingBlocks(const std::vector<BendingStencil>& stencils, const SweepPlan& plan) {
    BendingBlocks B;
    B.threads = plan.threads;
    int maxIndex = -1;
    for (const BendingStencil& s : stencils) maxIndex = std::max({maxIndex, s.i1, s.i2, s.i3, s.i4});
    std::vector<int> blockOf(static_cast<size_t>(maxIndex + 1), -1);  // last block a particle is in
    size_t group = 0;  // the plan's group of the next stencil
    for (const BendingStencil& s : stencils) {
        const int n = static_cast<int>(B.i1.size()), current = static_cast<int>(B.start.size()) - 1;
        const bool groupStarts = group < plan.groups.size() && plan.groups[group] == n;
        while (group < plan.groups.size() && plan.groups[group] <= n) ++group;
        const int ids[4] = {s.i1, s.i2, s.i3, s.i4};
        bool shares = false;
        for (int i : ids) shares = shares || blockOf[static_cast<size_t>(i)] == current;
        const int size = current < 0 ? 0 : n - B.start.back();
        // A new colour group: the blocks before it are one group (the shared-particle cut only
        // applies without a plan, where all blocks form one serial group).
        if (groupStarts && n > 0) B.groups.push_back(current + 1);
        if (current < 0 || shares || groupStarts || size == kBendingBlockSize) B.start.push_back(n);
        for (int i : ids) blockOf[static_cast<size_t>(i)] = static_cast<int>(B.start.size()) - 1;
        B.i1.push_back(s.i1);
        B.i2.push_back(s.i2);
        B.i3.push_back(s.i3);
        B.i4.push_back(s.i4);
        B.phi0.push_back(s.phi0);
    }
    B.start.push_back(static_cast<int>(B.i1.size()));
    B.groups.insert(B.groups.begin(), 0);
    B.groups.push_back(static_cast<int>(B.start.size()) - 1);
    return B;
}

bool bendingBlocksUseScatter() {
#ifdef CLOTHLAB_X86_DISPATCH
    static const bool avx512 = __builtin_cpu_supports("x86-64-v4");  // asked once
    return avx512;
#else
    return false;
#endif
}

void projectBendingBlocks(const BendingBlocks& blocks, const VectorX& w, double k, Matrix3X& p, BendingLoop loop) {
    sweepBlocks(blocks, w, k, 0.0, nullptr, p, loop);
}

void projectBendingBlocksXpbd(const BendingBlocks& blocks, const VectorX& w, double alphaTilde,
                              std::vector<double>& lambda, Matrix3X& p, BendingLoop loop) {
    sweepBlocks(blocks, w, 1.0, alphaTilde, lambda.data(), p, loop);
}

}  // namespace clothlab
