/// @file 07_self_collision.h
/// @brief Stage 07 (Position Based Dynamics): self-collision (Selbstkollision) with a spatial hash
/// (räumliches Hashing).
///
/// The student writes these functions in `exercises/07_self_collision/self_collision.cpp`;
/// the task sheet is `exercises/07_self_collision/README.md`. The hash follows Teschner et al.,
/// "Optimized spatial hashing for collision detection of deformable objects" (2003); the separation of
/// particle pairs follows Macklin et al., "Unified particle physics for real-time applications" (2014),
/// and Müller's Ten Minute Physics self-collision tutorial (Müller et al. 2007 separate a point from a
/// triangle instead): particles are sorted into the cells of an infinite grid of spacing s, the cells
/// are folded into a table of T buckets by a hash function, and a particle's neighbours within a
/// distance d ≤ s are found in the 3 × 3 × 3 cells around its own. Two particles i, j closer than
/// the self-collision thickness h are pushed apart: the inequality constraint
/// \f[ C(\vec p_i, \vec p_j) = |\vec p_i - \vec p_j| - h \ \ge\ 0. \f]
/// The framework (sim/pbd.cpp) leaves out the pairs closer than h at rest, |X_i − X_j| < h with X the
/// rest positions: those are the cloth's own neighbours, kept apart by its distance constraints, and
/// pushing them to h would fight those constraints.
#pragma once
#include <vector>

#include <Eigen/Core>

#include "clothlab/core/types.h"

namespace clothlab {

/// The spatial hash of N particles: the particle indices counting-sorted by bucket, in two flat arrays.
/// The table has T = cellStart.size() − 1 buckets; bucket b holds the particles
/// cellEntries[cellStart[b]], ..., cellEntries[cellStart[b + 1] − 1].
struct SpatialHash {
    double spacing = 1.0;          ///< cell size s, m: the cell of a point p is floor(p / s) per coordinate
    std::vector<int> cellStart;    ///< T + 1 offsets into cellEntries, cellStart[0] = 0, cellStart[T] = N, non-decreasing
    std::vector<int> cellEntries;  ///< the N particle indices 0..N−1, each once, grouped by bucket
};

/// Two particles closer than the query distance, i < j.
struct ParticlePair {
    int i = 0;  ///< the particle with the smaller index
    int j = 0;  ///< the particle with the larger index
};

/// The corrections of a particle pair: add dpi to p_i and dpj to p_j.
struct PairCorrection {
    Vec3 dpi{0, 0, 0};  ///< Δp_i, m
    Vec3 dpj{0, 0, 0};  ///< Δp_j, m
};

/// Exercise 7.1 — the cell of a point: the integer coordinates (⌊p_x/s⌋, ⌊p_y/s⌋, ⌊p_z/s⌋),
/// rounded towards −∞ (a point at −0.2 s lies in cell −1, not 0).
/// @param p        a point, m (|p|/s < 2^30)
/// @param spacing  the cell size s > 0, m
/// @return         the cell's integer coordinates
Eigen::Vector3i cellOf(const Vec3& p, double spacing);

/// Exercise 7.2 — the bucket of a cell in a table of T buckets (Teschner et al. 2003).
/// Requirements: a bucket in [0, T) for every cell, negative coordinates included; the same cell always
/// gives the same bucket; cells spread over the table like random numbers would (a block of T nearby
/// cells leaves about 1/e of the buckets empty; a sum of the coordinates, for example, would fill
/// only a few); no undefined behaviour (signed integer overflow) for any coordinates up to ±2^30.
/// @param cell       integer cell coordinates
/// @param tableSize  T ≥ 1
/// @return           the bucket, in [0, T)
int hashCell(const Eigen::Vector3i& cell, int tableSize);

/// Exercise 7.3 — build the spatial hash of the positions p by counting sort: count the particles per
/// bucket, turn the counts into start offsets (a prefix sum), then place each particle index.
/// Particle i lies in bucket hashCell(cellOf(p_i, s), T). Two flat arrays, no list per bucket.
/// @param p          positions, 3 x N, m
/// @param spacing    the cell size s > 0, m
/// @param tableSize  the number of buckets T ≥ 1
/// @return           the hash (see SpatialHash for what each array must hold)
SpatialHash buildSpatialHash(const Matrix3X& p, double spacing, int tableSize);

/// Exercise 7.4 — every pair of particles closer than d: each unordered pair {i, j} with
/// |p_i − p_j| < d exactly once, as (i, j) with i < j, in any order. The hash was built from these
/// positions with spacing ≥ d, so a neighbour of i lies in one of the 27 cells around i's cell.
/// Requirements: no pair missed (compared with all N(N − 1)/2 pairs); none twice, also when two of the
/// 27 cells fall into the same bucket (a small table); none farther apart than d.
/// @param p     positions, 3 x N, m (the ones the hash was built from)
/// @param hash  the spatial hash of p (exercise 7.3), spacing ≥ d
/// @param d     query distance, m, 0 < d ≤ hash.spacing
/// @return      the pairs
std::vector<ParticlePair> findNeighbourPairs(const Matrix3X& p, const SpatialHash& hash, double d);

/// Exercise 7.5 — project the separation constraint C = |p_i − p_j| − d ≥ 0 of a pair.
/// Requirements: an inequality: zero when C ≥ 0, and zero when both are pinned (w_i = w_j = 0);
/// otherwise the pair is moved apart along the line through them, n = (p_i − p_j)/|p_i − p_j|, to
/// exactly the distance d (C = 0 after one projection), each particle by a share proportional to its
/// inverse mass, so that the momentum m_i Δp_i + m_j Δp_j is zero (a pinned particle does not move).
/// Coincident particles (|p_i − p_j| < 1e-12 m, degenerate: notation table): the direction is
/// n = (0, 1, 0), never NaN (the one exception to the zero result: they must come apart).
/// @param pi, pj  predicted positions, m
/// @param wi, wj  inverse masses, 1/kg (0: pinned)
/// @param d       separation distance, m, d ≥ 0
/// @return        Δp_i, Δp_j
PairCorrection projectSeparation(const Vec3& pi, const Vec3& pj, double wi, double wj, double d);

/// Exercise 7.6 — friction between two cloth layers in contact, at position level (as static friction
/// in exercise 6.3, now between two moving particles). The relative displacement over the step is
/// r = (p_i − x_i) − (p_j − x_j); its tangential part r_t is r without its component along
/// n = (p_i − p_j)/|p_i − p_j| (coincident, |p_i − p_j| < 1e-12 m: n = (0, 1, 0)). Requirements: with the penetration depth δ
/// the separation removed (δ > 0) and the friction coefficient μ: if |r_t| < μ δ the layers stick,
/// the correction removes r_t entirely; otherwise it removes a part of length μ δ (they slide, slower).
/// The removal is shared like in exercise 7.5 (inverse-mass weighted, momentum zero); no normal
/// component; zero for μ = 0, δ ≤ 0, or both pinned.
/// @param pi, pj  predicted positions after the separation (exercise 7.5), m
/// @param xi, xj  positions at the start of the step, m
/// @param wi, wj  inverse masses, 1/kg
/// @param mu      friction coefficient μ ≥ 0 between the layers
/// @param depth   penetration depth δ = d − |p_i − p_j| before the separation, m
/// @return        Δp_i, Δp_j
PairCorrection layerFriction(const Vec3& pi, const Vec3& pj, const Vec3& xi, const Vec3& xj, double wi, double wj,
                             double mu, double depth);

}  // namespace clothlab
