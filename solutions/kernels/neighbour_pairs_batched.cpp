// The self-collision pairs without divisions (neighbour_pairs_batched.h).
#include "neighbour_pairs_batched.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace clothlab {
namespace {
/// The bucket of cell (x, y, z): Teschner et al.'s hash (2003), its low bits (mask = T − 1, T = 2^k).
inline uint32_t bucketOf(const Eigen::Vector3i& c, uint32_t mask) {
    return ((static_cast<uint32_t>(c.x()) * 73856093u) ^ (static_cast<uint32_t>(c.y()) * 19349663u) ^
            (static_cast<uint32_t>(c.z()) * 83492791u)) & mask;
}
}  // namespace

std::vector<ParticlePair> neighbourPairsBatched(const Matrix3X& p, double d) {
    const int n = static_cast<int>(p.cols());
    uint32_t buckets = 1;
    while (buckets < 2u * static_cast<uint32_t>(n)) buckets <<= 1;
    const uint32_t mask = buckets - 1;
    std::vector<Eigen::Vector3i> cell(static_cast<size_t>(n));
    std::vector<uint32_t> bucket(static_cast<size_t>(n));
    std::vector<int> start(static_cast<size_t>(buckets) + 1, 0), entries(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {  // the cells as exercise 7.1 has them: floor(p / d)
        cell[i] = Eigen::Vector3i(static_cast<int>(std::floor(p(0, i) / d)), static_cast<int>(std::floor(p(1, i) / d)),
                                  static_cast<int>(std::floor(p(2, i) / d)));
        bucket[i] = bucketOf(cell[i], mask);
        ++start[bucket[i]];
    }
    for (uint32_t b = 1; b <= buckets; ++b) start[b] += start[b - 1];  // the end of each bucket
    for (int i = 0; i < n; ++i) entries[--start[bucket[i]]] = i;      // now its start
    // Each pair from one side: particle i with the later particles of its own cell, and with every
    // particle of the 13 cells after its own (the half of the 26 neighbours with (dx, dy, dz) > 0 in
    // lexicographic order); the other 13 find i from their side.
    std::vector<ParticlePair> pairs;
    const double d2 = d * d;
    for (int i = 0; i < n; ++i)
        for (int dx = 0; dx <= 1; ++dx)
            for (int dy = dx ? -1 : 0; dy <= 1; ++dy)
                for (int dz = dx || dy ? -1 : 0; dz <= 1; ++dz) {
                    const Eigen::Vector3i c = cell[i] + Eigen::Vector3i(dx, dy, dz);
                    const bool own = dx == 0 && dy == 0 && dz == 0;
                    const uint32_t b = bucketOf(c, mask);
                    for (int k = start[b]; k < start[b + 1]; ++k) {
                        const int j = entries[k];
                        if ((!own || j > i) && cell[j] == c && (p.col(i) - p.col(j)).squaredNorm() < d2)  // another cell: j ≠ i
                            pairs.push_back({std::min(i, j), std::max(i, j)});
                    }
                }
    return pairs;
}

}  // namespace clothlab
