// Stage 07 in the test process: each function forwards to the submission process (remote/peer.h).
#include "remote/functions.h"
#include "remote/peer.h"

namespace clothlab {

using remote::Invoke;
using remote::submissionProcess;

Eigen::Vector3i cellOf(const Vec3& p, double spacing) {
    return Invoke<decltype(cellOf)>::call(submissionProcess(), remote::k_cellOf, "cellOf", p, spacing);
}

int hashCell(const Eigen::Vector3i& cell, int tableSize) {
    return Invoke<decltype(hashCell)>::call(submissionProcess(), remote::k_hashCell, "hashCell", cell, tableSize);
}

SpatialHash buildSpatialHash(const Matrix3X& p, double spacing, int tableSize) {
    return Invoke<decltype(buildSpatialHash)>::call(submissionProcess(), remote::k_buildSpatialHash, "buildSpatialHash", p, spacing,
                                                    tableSize);
}

std::vector<ParticlePair> findNeighbourPairs(const Matrix3X& p, const SpatialHash& hash, double d) {
    return Invoke<decltype(findNeighbourPairs)>::call(submissionProcess(), remote::k_findNeighbourPairs, "findNeighbourPairs", p, hash, d);
}

PairCorrection projectSeparation(const Vec3& pi, const Vec3& pj, double wi, double wj, double d) {
    return Invoke<decltype(projectSeparation)>::call(submissionProcess(), remote::k_projectSeparation, "projectSeparation", pi, pj, wi,
                                                     wj, d);
}

PairCorrection layerFriction(const Vec3& pi, const Vec3& pj, const Vec3& xi, const Vec3& xj, double wi, double wj, double mu,
                             double depth) {
    return Invoke<decltype(layerFriction)>::call(submissionProcess(), remote::k_layerFriction, "layerFriction", pi, pj, xi, xj, wi, wj,
                                                 mu, depth);
}

// The framework's sweep over this stage's pairs, sent whole (remote/functions.h: 901–906).

void wrappedSelfCollisionSweep(const std::vector<DistanceLink>& pairs, const Matrix3X& x, const VectorX& w, double mu, Matrix3X& p) __asm__("__wrap__ZN8clothlab25projectSelfCollisionSweepERKSt6vectorINS_12DistanceLinkESaIS1_EERKN5Eigen6MatrixIdLi3ELin1ELi0ELi3ELin1EEERKNS7_IdLin1ELi1ELi0ELin1ELi1EEEdRS8_");
void wrappedSelfCollisionSweep(const std::vector<DistanceLink>& pairs, const Matrix3X& x, const VectorX& w, double mu, Matrix3X& p) {
    Invoke<decltype(projectSelfCollisionSweep)>::call(submissionProcess(), remote::k_projectSelfCollisionSweep, "projectSelfCollisionSweep",
                                                      pairs, x, w, mu, p);
}

}  // namespace clothlab
