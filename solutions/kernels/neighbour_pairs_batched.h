/// @file neighbour_pairs_batched.h
/// @brief A fast search for the self-collision pairs, for the reference demos and benchmarks
/// (instructor copy only).
///
/// The solver's default search is exercises 7.1–7.4: the particles counting-sorted into the buckets of
/// a spatial hash (cell size d, T = 2N buckets), then for each particle the buckets of the 27 cells
/// around its own, each bucket once. Most of its time goes to the remainders (two 64-bit divisions per
/// cell: 27 · 2 per particle) and to the list of buckets already searched. This file finds the same
/// pairs with a table of \f$T = 2^k \ge 2N\f$ buckets, so that the bucket is the hash's low bits (a
/// mask, no division), and with each particle's cell kept: a neighbour cell's bucket is searched for
/// the particles of that cell only, so two cells that share a bucket never give a pair twice and no
/// list of searched buckets is needed; and each pair is looked for from one side only (a particle's
/// own cell and the 13 cells after it), half the buckets of the exercise. It is a solved stage 07, so `./lab release` leaves it out.
#pragma once
#include <vector>

#include "clothlab/core/types.h"
#include "clothlab/exercise/07_self_collision.h"

namespace clothlab {

/// Every pair of particles closer than d, each once as (i, j) with i < j (exercise 7.4's result;
/// the order may differ from it).
/// @param p  positions, 3 x N, m (|p|/d < 2^30)
/// @param d  the query distance, m, d > 0
/// @return   the pairs
std::vector<ParticlePair> neighbourPairsBatched(const Matrix3X& p, double d);

}  // namespace clothlab
