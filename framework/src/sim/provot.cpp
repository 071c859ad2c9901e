#include "clothlab/sim/provot.h"

#include <cstdint>

namespace clothlab {

// The passes of provot.h's header, without re-reading springs that cannot have changed: a spring
// found within its limit stays within until one of its end points moves. So after the first pass over
// all springs, a pass only looks at the springs at particles that a correction has moved since they
// were last looked at ("dirty" springs, one bit each), in the same order as a full pass. The skipped
// springs are exactly those a full pass would find within the limit, so the corrections, their order
// and the number of passes are those of full passes over all springs, bit for bit
// (tests/framework/provot_test.cpp compares the two).
int applyProvotConstraint(const std::vector<Spring>& springs, Matrix3X& x, Matrix3X& v, const VectorX& w, double tau,
                          double dt, int max_passes) {
    const int S = static_cast<int>(springs.size()), N = static_cast<int>(x.cols());
    // The springs at each particle: springsAt[first[i] .. first[i + 1] − 1].
    std::vector<int> first(static_cast<size_t>(N) + 1, 0), springsAt(2 * static_cast<size_t>(S));
    for (const Spring& s : springs) ++first[static_cast<size_t>(s.i) + 1], ++first[static_cast<size_t>(s.j) + 1];
    for (int i = 0; i < N; ++i) first[static_cast<size_t>(i) + 1] += first[static_cast<size_t>(i)];
    {
        std::vector<int> fill(first.begin(), first.end() - 1);
        for (int k = 0; k < S; ++k) {
            springsAt[static_cast<size_t>(fill[static_cast<size_t>(springs[static_cast<size_t>(k)].i)]++)] = k;
            springsAt[static_cast<size_t>(fill[static_cast<size_t>(springs[static_cast<size_t>(k)].j)]++)] = k;
        }
    }
    // Spring k is dirty (bit k % 64 of word k / 64): to be looked at; at first all of them.
    std::vector<std::uint64_t> dirty((static_cast<size_t>(S) + 63) / 64, ~std::uint64_t{0});
    if (S % 64) dirty.back() = (std::uint64_t{1} << (S % 64)) - 1;
    const auto touch = [&](int i) {  // particle i moved: its springs are dirty
        for (int a = first[static_cast<size_t>(i)]; a < first[static_cast<size_t>(i) + 1]; ++a) {
            const int k = springsAt[static_cast<size_t>(a)];
            dirty[static_cast<size_t>(k) / 64] |= std::uint64_t{1} << (k % 64);
        }
    };
    int pass = 0;
    while (pass < max_passes) {
        ++pass;
        bool all_within = true;
        for (size_t word = 0; word < dirty.size(); ++word) {
            // the dirty springs of this word in increasing order; springs made dirty behind the
            // current one wait for the next pass, as in a full pass
            for (int from = 0; from < 64;) {
                const std::uint64_t ahead = dirty[word] & (~std::uint64_t{0} << from);
                if (!ahead) break;
                const int bit = __builtin_ctzll(ahead);
                dirty[word] &= ~(std::uint64_t{1} << bit);
                from = bit + 1;
                const Spring& s = springs[word * 64 + static_cast<size_t>(bit)];
                const double w_sum = w[s.i] + w[s.j];
                if (!(s.l0 > 0.0) || w_sum == 0.0) continue;
                const Vec3 d = x.col(s.j) - x.col(s.i);
                const double l_max = (1.0 + tau) * s.l0;
                if (d.squaredNorm() <= l_max * l_max) continue;  // within the limit (most springs): no square root
                const double l = d.norm();
                if (l > l_max * (1.0 + 1e-6)) all_within = false;
                const Vec3 shift = (l - l_max) / l * d;  // δ d̂
                const Vec3 dxi = (w[s.i] / w_sum) * shift, dxj = -(w[s.j] / w_sum) * shift;
                x.col(s.i) += dxi;
                x.col(s.j) += dxj;
                v.col(s.i) += dxi / dt;
                v.col(s.j) += dxj / dt;
                touch(s.i);
                touch(s.j);
            }
        }
        if (all_within) break;
    }
    return pass;
}

}  // namespace clothlab
