// The batched distance sweep (solver.kernel "batched"); formula in distance_batched.h.
//
// How it is made fast (none of this is needed for the exercises): the formula sits in the loop
// instead of a call per link; the links of a colour group share no particle, so `#pragma omp simd`
// may run them side by side (gather and scatter instructions with AVX-512, built by `target_clones`
// next to a plain x86-64 loop); no branches, the cases without a correction are selects. The file is
// compiled with -ffp-contract=off (cmake/extensions.cmake): without fused multiply-adds the vector
// loop and its scalar remainder round alike, so the result does not depend on where a thread's share
// starts (bit-identical for every number of threads).
#include "distance_batched.h"

#include <algorithm>
#include <cmath>

namespace clothlab {
namespace {

// Links begin .. end − 1 (sharing no particle): PBD (Xpbd = false: α̃ = 0, no λ) or XPBD (k = 1).
template <bool Xpbd>
[[gnu::always_inline]] inline void linkLoop(const int* I, const int* J, const double* D, int begin, int end,
                                            const double* w, double k, double alphaTilde, double* lambda, double* P) {
#pragma omp simd
    for (int n = begin; n < end; ++n) {
        const int i = 3 * I[n], j = 3 * J[n];
        const double ex = P[i] - P[j], ey = P[i + 1] - P[j + 1], ez = P[i + 2] - P[j + 2];
        const double len = std::sqrt(ex * ex + ey * ey + ez * ez);
        const double wi = w[I[n]], wj = w[J[n]], W = wi + wj;
        double f = Xpbd ? (len - D[n] + alphaTilde * lambda[n]) / ((W + alphaTilde) * len) : k * (len - D[n]) / (W * len);
        f = len < 1e-12 || W <= 0.0 ? 0.0 : f;  // coincident points, both pinned: no correction
        if constexpr (Xpbd) lambda[n] -= f * len;
        const double fi = f * wi, fj = f * wj;
        P[i] -= fi * ex, P[i + 1] -= fi * ey, P[i + 2] -= fi * ez;
        P[j] += fj * ex, P[j + 1] += fj * ey, P[j + 2] += fj * ez;
    }
}

// target_clones with "arch=x86-64-vN" needs GCC 12 and ifunc (glibc); elsewhere one plain build.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12 && defined(__x86_64__) && defined(__GLIBC__)
#define CLOTHLAB_CLONES __attribute__((target_clones("default", "arch=x86-64-v4")))
#else
#define CLOTHLAB_CLONES
#endif
CLOTHLAB_CLONES void sweepLinksPbd(const int* I, const int* J, const double* D, int begin, int end, const double* w,
                                   double k, double* P) {
    linkLoop<false>(I, J, D, begin, end, w, k, 0.0, nullptr, P);
}
CLOTHLAB_CLONES void sweepLinksXpbd(const int* I, const int* J, const double* D, int begin, int end, const double* w,
                                    double alphaTilde, double* lambda, double* P) {
    linkLoop<true>(I, J, D, begin, end, w, 1.0, alphaTilde, lambda, P);
}

}  // namespace

DistanceArrays distanceArrays(const std::vector<DistanceLink>& links, const SweepPlan& plan) {
    DistanceArrays A;
    std::vector<Eigen::Vector4i> particles;
    int maxIndex = -1;
    for (const DistanceLink& L : links) {
        A.i.push_back(L.i);
        A.j.push_back(L.j);
        A.d.push_back(L.d);
        particles.emplace_back(L.i, L.j, -1, -1);
        maxIndex = std::max({maxIndex, L.i, L.j});
    }
    A.groups = plan.groups.empty() ? sweepPlan(particles, maxIndex + 1, 1).groups : plan.groups;
    A.threads = plan.groups.empty() ? 1 : plan.threads;
    return A;
}

void projectDistanceArrays(const DistanceArrays& links, const VectorX& w, double k, Matrix3X& p) {
    forEachGroupShare(links.groups, links.threads, kParallelGroup, [&](int begin, int end) {
        sweepLinksPbd(links.i.data(), links.j.data(), links.d.data(), begin, end, w.data(), k, p.data());
    });
}

void projectDistanceArraysXpbd(const DistanceArrays& links, const VectorX& w, double alphaTilde,
                               std::vector<double>& lambda, Matrix3X& p) {
    forEachGroupShare(links.groups, links.threads, kParallelGroup, [&](int begin, int end) {
        sweepLinksXpbd(links.i.data(), links.j.data(), links.d.data(), begin, end, w.data(), alphaTilde, lambda.data(),
                       p.data());
    });
}

}  // namespace clothlab
