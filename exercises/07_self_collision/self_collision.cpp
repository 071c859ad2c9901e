// Stage 07 — self-collision with a spatial hash.
// Task sheet: exercises/07_self_collision/README.md
// Contract (arguments, units, requirements): framework/include/clothlab/exercise/07_self_collision.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 07
// Stuck? `./lab hint 7.1` (or 7.2, ...) asks a question and names the slide; add 2 for one sub-step, 3 for the formula.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/07_self_collision.h"

namespace clothlab {

// ---- Task 7.1: the cell of a point ---------------------------------------------------------
Eigen::Vector3i cellOf(const Vec3& p, double spacing) {
    // TODO 7.1: the cell of a point (task sheet 7.1; contract in the header)
    (void)p; (void)spacing;
    throw NotImplemented("exercise 7.1 cellOf");
}

// ---- Task 7.2: the bucket of a cell ----------------------------------------------------------
int hashCell(const Eigen::Vector3i& cell, int tableSize) {
    // TODO 7.2: the bucket of a cell (task sheet 7.2; contract in the header)
    (void)cell; (void)tableSize;
    throw NotImplemented("exercise 7.2 hashCell");
}

// ---- Task 7.3: counting sort into buckets ----------------------------------------------------
SpatialHash buildSpatialHash(const Matrix3X& p, double spacing, int tableSize) {
    // TODO 7.3: build the spatial hash (task sheet 7.3; contract in the header)
    (void)p; (void)spacing; (void)tableSize;
    throw NotImplemented("exercise 7.3 buildSpatialHash");
}

// ---- Task 7.4: the pairs closer than d -------------------------------------------------------
std::vector<ParticlePair> findNeighbourPairs(const Matrix3X& p, const SpatialHash& hash, double d) {
    // TODO 7.4: every pair closer than d, once (task sheet 7.4; contract in the header)
    (void)p; (void)hash; (void)d;
    throw NotImplemented("exercise 7.4 findNeighbourPairs");
}

// ---- Task 7.5: separation of a pair --------------------------------------------------------------
PairCorrection projectSeparation(const Vec3& pi, const Vec3& pj, double wi, double wj, double d) {
    // TODO 7.5: project the separation constraint (task sheet 7.5; contract in the header)
    (void)pi; (void)pj; (void)wi; (void)wj; (void)d;
    throw NotImplemented("exercise 7.5 projectSeparation");
}

// ---- Task 7.6: friction between the layers -------------------------------------------------------
PairCorrection layerFriction(const Vec3& pi, const Vec3& pj, const Vec3& xi, const Vec3& xj, double wi, double wj,
                             double mu, double depth) {
    // TODO 7.6: friction between the layers (task sheet 7.6; contract in the header)
    (void)pi; (void)pj; (void)xi; (void)xj; (void)wi; (void)wj; (void)mu; (void)depth;
    throw NotImplemented("exercise 7.6 layerFriction");
}

}  // namespace clothlab
