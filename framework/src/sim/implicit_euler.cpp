#include "clothlab/sim/implicit_euler.h"

#include <algorithm>

namespace clothlab {
namespace {
using Triplet = Eigen::Triplet<double>;
using Mat3 = Eigen::Matrix3d;

// Adds the blocks +B at (a, a) and (b, b), −B at (a, b) and (b, a); pinned particles (−1) are skipped.
void addPairBlocks(std::vector<Triplet>& t, int a, int b, const Mat3& B) {
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            if (a >= 0) t.emplace_back(a + r, a + c, B(r, c));
            if (b >= 0) t.emplace_back(b + r, b + c, B(r, c));
            if (a >= 0 && b >= 0) {
                t.emplace_back(a + r, b + c, -B(r, c));
                t.emplace_back(b + r, a + c, -B(r, c));
            }
        }
}
}  // namespace

void addSpringJacobians(const std::vector<Spring>& springs, const Matrix3X& x, const std::vector<int>& index,
                        std::vector<Triplet>& K, std::vector<Triplet>& D) {
    for (const Spring& s : springs) {
        const int a = index[static_cast<size_t>(s.i)], b = index[static_cast<size_t>(s.j)];
        if (a < 0 && b < 0) continue;
        const Vec3 d = x.col(s.j) - x.col(s.i);
        const double l = d.norm();
        Mat3 Kjj = Mat3::Zero(), Djj = Mat3::Zero();
        if (l > 1e-12) {
            const Vec3 n = d / l;
            const Mat3 nn = n * n.transpose();
            Kjj = -s.k * (nn + std::max(0.0, 1.0 - s.l0 / l) * (Mat3::Identity() - nn));
            Djj = -s.kd * nn;
        }
        addPairBlocks(K, a, b, Kjj);
        addPairBlocks(D, a, b, Djj);
    }
}

bool ImplicitEulerSolver::step(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force,
                               const std::vector<Spring>& springs, double c, double dt) {
    const int n = static_cast<int>(x.cols());
    // Unknowns: the 3 velocity changes of every free particle.
    if (static_cast<int>(index_.size()) != n) {
        index_.assign(static_cast<size_t>(n), -1);
        int rows = 0;
        for (int i = 0; i < n; ++i)
            if (w[i] > 0.0) index_[static_cast<size_t>(i)] = 3 * (rows++);
        analysed_ = false;
    }
    const int unknowns = 3 * static_cast<int>(std::count_if(index_.begin(), index_.end(), [](int r) { return r >= 0; }));

    // (1) forces and Jacobians at the current state
    f_.setZero(3, n);
    force(x, v, f_);
    K_.clear(), D_.clear();
    addSpringJacobians(springs, x, index_, K_, D_);

    // (2) A = M - dt D - dt² K (with the global damping D_ii -= c I), b = dt (f + dt K v)
    std::vector<Triplet> a;
    a.reserve(K_.size() + D_.size() + static_cast<size_t>(unknowns));
    for (int i = 0; i < n; ++i) {
        const int r = index_[static_cast<size_t>(i)];
        if (r >= 0)
            for (int k = 0; k < 3; ++k) a.emplace_back(r + k, r + k, 1.0 / w[i] + dt * c);
    }
    for (const Triplet& t : K_) a.emplace_back(t.row(), t.col(), -dt * dt * t.value());
    for (const Triplet& t : D_) a.emplace_back(t.row(), t.col(), -dt * t.value());
    A_.resize(unknowns, unknowns);
    A_.setFromTriplets(a.begin(), a.end());

    VectorX vfree(unknowns), b(unknowns);
    for (int i = 0; i < n; ++i)
        if (const int r = index_[static_cast<size_t>(i)]; r >= 0) {
            vfree.segment<3>(r) = v.col(i);
            b.segment<3>(r) = dt * f_.col(i);
        }
    SparseMatrix K(unknowns, unknowns);
    K.setFromTriplets(K_.begin(), K_.end());
    b += dt * dt * (K * vfree);

    // (3) solve A Δv = b
    if (!analysed_) ldlt_.analyzePattern(A_), analysed_ = true;
    ldlt_.factorize(A_);
    if (ldlt_.info() != Eigen::Success) return false;
    const VectorX dv = ldlt_.solve(b);
    if (ldlt_.info() != Eigen::Success || !dv.allFinite()) return false;

    // (4) v += Δv, x += dt v (pinned particles keep their velocity)
    for (int i = 0; i < n; ++i)
        if (const int r = index_[static_cast<size_t>(i)]; r >= 0) v.col(i) += dv.segment<3>(r);
    x += dt * v;
    return true;
}

}  // namespace clothlab
