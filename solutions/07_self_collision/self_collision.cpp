// Stage 07 — self-collision with a spatial hash (reference solution).
// Task sheet: exercises/07_self_collision/README.md
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "clothlab/exercise/07_self_collision.h"

namespace clothlab {

namespace {
// The unit direction from p_j to p_i; (0, 1, 0) when they coincide.
Vec3 pairDirection(const Vec3& pi, const Vec3& pj) {
    const Vec3 diff = pi - pj;
    const double len = diff.norm();
    return len >= 1e-12 ? Vec3(diff / len) : Vec3(0, 1, 0);  // degenerate: +y
}
}  // namespace

// ---- Task 7.1: the cell of a point ---------------------------------------------------------
Eigen::Vector3i cellOf(const Vec3& p, double spacing) {
    return Eigen::Vector3i(static_cast<int>(std::floor(p.x() / spacing)), static_cast<int>(std::floor(p.y() / spacing)),
                           static_cast<int>(std::floor(p.z() / spacing)));
}

// ---- Task 7.2: the bucket of a cell ----------------------------------------------------------
int hashCell(const Eigen::Vector3i& cell, int tableSize) {
    const int64_t h = (int64_t{cell.x()} * 73856093) ^ (int64_t{cell.y()} * 19349663) ^ (int64_t{cell.z()} * 83492791);
    return static_cast<int>(((h % tableSize) + tableSize) % tableSize);
}

// ---- Task 7.3: counting sort into buckets ----------------------------------------------------
SpatialHash buildSpatialHash(const Matrix3X& p, double spacing, int tableSize) {
    SpatialHash hash;
    hash.spacing = spacing;
    hash.cellStart.assign(static_cast<size_t>(tableSize) + 1, 0);
    hash.cellEntries.assign(static_cast<size_t>(p.cols()), 0);
    std::vector<int> bucket(static_cast<size_t>(p.cols()));
    for (int i = 0; i < p.cols(); ++i) {
        bucket[i] = hashCell(cellOf(p.col(i), spacing), tableSize);
        ++hash.cellStart[bucket[i]];
    }
    int start = 0;
    for (int b = 0; b <= tableSize; ++b) {
        start += hash.cellStart[b];
        hash.cellStart[b] = start;  // for now: the end of bucket b
    }
    for (int i = 0; i < p.cols(); ++i) hash.cellEntries[--hash.cellStart[bucket[i]]] = i;
    return hash;
}

// ---- Task 7.4: the pairs closer than d -------------------------------------------------------
std::vector<ParticlePair> findNeighbourPairs(const Matrix3X& p, const SpatialHash& hash, double d) {
    std::vector<ParticlePair> pairs;
    const int tableSize = static_cast<int>(hash.cellStart.size()) - 1;
    std::vector<int> visited;  // the buckets already searched for this particle
    for (int i = 0; i < p.cols(); ++i) {
        const Eigen::Vector3i c = cellOf(p.col(i), hash.spacing);
        visited.clear();
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    const int b = hashCell(c + Eigen::Vector3i(dx, dy, dz), tableSize);
                    if (std::find(visited.begin(), visited.end(), b) != visited.end()) continue;
                    visited.push_back(b);
                    for (int k = hash.cellStart[b]; k < hash.cellStart[b + 1]; ++k) {
                        const int j = hash.cellEntries[k];
                        if (j > i && (p.col(i) - p.col(j)).squaredNorm() < d * d) pairs.push_back({i, j});
                    }
                }
    }
    return pairs;
}

// ---- Task 7.5: separation of a pair --------------------------------------------------------------
PairCorrection projectSeparation(const Vec3& pi, const Vec3& pj, double wi, double wj, double d) {
    const double dist = (pi - pj).norm(), wsum = wi + wj;
    if (dist >= d || wsum <= 0.0) return {};
    const Vec3 n = pairDirection(pi, pj);
    const double push = d - dist;
    return {wi / wsum * push * n, -wj / wsum * push * n};
}

// ---- Task 7.6: friction between the layers -------------------------------------------------------
PairCorrection layerFriction(const Vec3& pi, const Vec3& pj, const Vec3& xi, const Vec3& xj, double wi, double wj,
                             double mu, double depth) {
    const double wsum = wi + wj;
    if (mu <= 0.0 || depth <= 0.0 || wsum <= 0.0) return {};
    const Vec3 n = pairDirection(pi, pj);
    const Vec3 r = (pi - xi) - (pj - xj);
    Vec3 rt = r - r.dot(n) * n;
    const double slip = rt.norm();
    if (slip >= mu * depth) rt *= mu * depth / slip;  // sliding: remove only mu * depth of the slip
    return {-wi / wsum * rt, wj / wsum * rt};
}

}  // namespace clothlab
