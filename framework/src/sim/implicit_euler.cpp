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

void springJacobianBlocks(const Spring& s, const Matrix3X& x, Mat3& Kjj, Mat3& Djj) {
    const Vec3 d = x.col(s.j) - x.col(s.i);
    const double l = d.norm();
    if (!(l > 1e-12)) {  // no direction: no stiffness (hookeForce returns zero here too)
        Kjj.setZero(), Djj.setZero();
        return;
    }
    const Vec3 n = d / l;
    const Mat3 nn = n * n.transpose();
    Kjj = -s.k * (nn + std::max(0.0, 1.0 - s.l0 / l) * (Mat3::Identity() - nn));  // clamped: never indefinite
    Djj = -s.kd * nn;
}

void addSpringJacobians(const std::vector<Spring>& springs, const Matrix3X& x, const std::vector<int>& index,
                        std::vector<Triplet>& K, std::vector<Triplet>& D) {
    for (const Spring& s : springs) {
        const int a = index[static_cast<size_t>(s.i)], b = index[static_cast<size_t>(s.j)];
        if (a < 0 && b < 0) continue;
        Mat3 Kjj, Djj;
        springJacobianBlocks(s, x, Kjj, Djj);
        addPairBlocks(K, a, b, Kjj);
        addPairBlocks(D, a, b, Djj);
    }
}

int ImplicitEulerSolver::offset(int r, int c) { return static_cast<int>(&A_.coeffRef(r, c) - A_.valuePtr()); }

void ImplicitEulerSolver::buildPattern(const VectorX& w, const std::vector<Spring>& springs) {
    const int n = static_cast<int>(w.size());
    index_.assign(static_cast<size_t>(n), -1);
    int unknowns = 0;
    for (int i = 0; i < n; ++i)
        if (w[i] > 0.0) index_[static_cast<size_t>(i)] = unknowns, unknowns += 3;
    // Pattern: diagonal plus every spring's blocks (values are filled in each step).
    std::vector<Triplet> t;
    for (int r = 0; r < unknowns; ++r) t.emplace_back(r, r, 0.0);
    for (const Spring& s : springs)
        addPairBlocks(t, index_[static_cast<size_t>(s.i)], index_[static_cast<size_t>(s.j)], Mat3::Zero());
    A_.resize(unknowns, unknowns);
    A_.setFromTriplets(t.begin(), t.end());
    A_.makeCompressed();
    diag_.resize(static_cast<size_t>(unknowns));
    for (int r = 0; r < unknowns; ++r) diag_[static_cast<size_t>(r)] = offset(r, r);
    blocks_.assign(springs.size(), {});
    for (size_t k = 0; k < springs.size(); ++k) {
        const int a = index_[static_cast<size_t>(springs[k].i)], b = index_[static_cast<size_t>(springs[k].j)];
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                const int e = 3 * r + c;
                blocks_[k][e] = a >= 0 ? offset(a + r, a + c) : -1;
                blocks_[k][9 + e] = b >= 0 ? offset(b + r, b + c) : -1;
                blocks_[k][18 + e] = a >= 0 && b >= 0 ? offset(a + r, b + c) : -1;
                blocks_[k][27 + e] = a >= 0 && b >= 0 ? offset(b + r, a + c) : -1;
            }
    }
    pattern_springs_ = springs.size();
    use_cg_ = unknowns > 1500;
    dv_ = VectorX::Zero(unknowns);
    if (use_cg_) cg_.setTolerance(1e-10);
    else ldlt_.analyzePattern(A_);
}

bool ImplicitEulerSolver::step(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force,
                               const std::vector<Spring>& springs, double c, double dt) {
    const int n = static_cast<int>(x.cols());
    bool same_pins = static_cast<int>(index_.size()) == n && pattern_springs_ == springs.size();
    for (int i = 0; same_pins && i < n; ++i) same_pins = (w[i] > 0.0) == (index_[static_cast<size_t>(i)] >= 0);
    if (!same_pins) buildPattern(w, springs);  // first step, or particles were pinned or released
    const int unknowns = static_cast<int>(A_.rows());
    if (unknowns == 0) {  // everything pinned
        x += dt * v;
        return true;
    }

    // (1) forces at the current state: b = dt f
    f_.setZero(3, n);
    force(x, v, f_);
    b_.resize(unknowns);
    for (int i = 0; i < n; ++i)
        if (const int r = index_[static_cast<size_t>(i)]; r >= 0) b_.segment<3>(r) = dt * f_.col(i);

    // (2) A = M - dt D - dt² K (global damping: D_ii = -c I), and b += dt² K v
    double* A = A_.valuePtr();
    std::fill(A, A + A_.nonZeros(), 0.0);
    for (int i = 0; i < n; ++i)
        if (const int r = index_[static_cast<size_t>(i)]; r >= 0)
            for (int k = 0; k < 3; ++k) A[diag_[static_cast<size_t>(r + k)]] = 1.0 / w[i] + dt * c;
    Mat3 Kjj, Djj;
    for (size_t k = 0; k < springs.size(); ++k) {
        const Spring& s = springs[k];
        const int a = index_[static_cast<size_t>(s.i)], b = index_[static_cast<size_t>(s.j)];
        if (a < 0 && b < 0) continue;
        springJacobianBlocks(s, x, Kjj, Djj);
        const Mat3 B = -dt * dt * Kjj - dt * Djj;  // block of A at (a, a) and (b, b); −B at (a, b) and (b, a)
        const std::array<int, 36>& o = blocks_[k];
        for (int e = 0; e < 9; ++e) {
            const double value = B(e / 3, e % 3);
            if (o[e] >= 0) A[o[e]] += value;
            if (o[9 + e] >= 0) A[o[9 + e]] += value;
            if (o[18 + e] >= 0) A[o[18 + e]] -= value, A[o[27 + e]] -= value;
        }
        const Vec3 Kv = dt * dt * Kjj * (v.col(s.j) - v.col(s.i));  // (K v)_j = Kjj (v_j − v_i), (K v)_i = −(K v)_j
        if (b >= 0) b_.segment<3>(b) += Kv;
        if (a >= 0) b_.segment<3>(a) -= Kv;
    }

    // (3) solve A Δv = b: sparse Cholesky (pattern analysed once) or, for large systems, CG
    if (use_cg_) {
        cg_.compute(A_);
        dv_ = cg_.solveWithGuess(b_, dv_);
        // Not converged within 2n iterations (extremely stiff): the finite iterate is used; should the
        // motion then grow, runSimulation() reports it as unstable.
        if ((cg_.info() != Eigen::Success && cg_.info() != Eigen::NoConvergence) || !dv_.allFinite()) return false;
    } else {
        ldlt_.factorize(A_);
        if (ldlt_.info() != Eigen::Success) return false;
        dv_ = ldlt_.solve(b_);
        if (ldlt_.info() != Eigen::Success || !dv_.allFinite()) return false;
    }
    const VectorX& dv = dv_;

    // (4) v += Δv, x += dt v (pinned particles keep their velocity)
    for (int i = 0; i < n; ++i)
        if (const int r = index_[static_cast<size_t>(i)]; r >= 0) v.col(i) += dv.segment<3>(r);
    x += dt * v;
    return true;
}

}  // namespace clothlab
