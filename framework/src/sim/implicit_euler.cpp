#include "clothlab/sim/implicit_euler.h"

#include <algorithm>
#include <cmath>

#include "clothlab/sim/sweeps.h"
#include "clothlab/sim/team.h"

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

constexpr double kTolerance = 1e-3;  // relative residual |b − A Δv| / |b| of the iterative solves
// ImplicitSolve::Auto: the exact solve up to this many unknowns (100 free particles: the springs,
// chains and small cloths of the stability studies, where it is cheap and robust at extreme stiffness
// and mass ratios); above, the factor's fill makes it slower than block CG on every cloth measured
// (bench_mfn's ImplicitLectureCloth, docs/performance.md).
constexpr int kCholeskyMaxUnknowns = 300;
constexpr int kChunk = 1024;         // particles per partial sum of a dot product (fixed: the same sum on any number of threads)

/// Σ_i a_i · b_i over the columns of two 3 x N matrices, in fixed chunks added in order (the same
/// bits for every number of threads).
double dot(const Matrix3X& a, const Matrix3X& b, int threads) {
    const int n = static_cast<int>(a.cols()), chunks = (n + kChunk - 1) / kChunk;
    std::vector<double> part(static_cast<size_t>(chunks));
    forEachShare(chunks, threads, 2, [&](int begin, int end) {
        for (int c = begin; c < end; ++c) {
            const int first = c * kChunk, count = std::min(kChunk, n - first);
            part[static_cast<size_t>(c)] = (a.middleCols(first, count).array() * b.middleCols(first, count).array()).sum();
        }
    });
    double sum = 0.0;
    for (double p : part) sum += p;
    return sum;
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

void ImplicitEulerSolver::buildBlocks(const VectorX& w, const std::vector<Spring>& springs) {
    const int n = static_cast<int>(w.size());
    // Per particle the springs it belongs to and their other ends (CSR): entries adjStart_[i] .. adjStart_[i+1] − 1.
    adjStart_.assign(static_cast<size_t>(n) + 1, 0);
    for (const Spring& s : springs) ++adjStart_[static_cast<size_t>(s.i) + 1], ++adjStart_[static_cast<size_t>(s.j) + 1];
    for (int i = 0; i < n; ++i) adjStart_[static_cast<size_t>(i) + 1] += adjStart_[static_cast<size_t>(i)];
    adj_.resize(static_cast<size_t>(adjStart_.back()));
    std::vector<int> fill(adjStart_.begin(), adjStart_.end() - 1);
    for (size_t k = 0; k < springs.size(); ++k) {
        const int i = springs[k].i, j = springs[k].j;
        adj_[static_cast<size_t>(fill[static_cast<size_t>(i)]++)] = {static_cast<int>(k), j};
        adj_[static_cast<size_t>(fill[static_cast<size_t>(j)]++)] = {static_cast<int>(k), i};
    }
    B_.resize(springs.size());
    Kv_.resize(springs.size());
    Dinv_.resize(static_cast<size_t>(n));
    mass_.resize(n);
    dvBlock_.setZero(3, n);
}

void ImplicitEulerSolver::applyA(const Matrix3X& x, Matrix3X& y) const {
    // (A x)_i = (m_i + Δt c) x_i + Σ_{springs s of i} B_s (x_i − x_other), B_s u = a_s (n_s·u) n_s + b_s u;
    // pinned rows are zero (x is zero there)
    const int n = static_cast<int>(x.cols());
    forEachShare(n, threads_, kParallelGroup, [&](int first, int last) {
        for (int i = first; i < last; ++i) {
            if (!(mass_[i] > 0.0)) {  // pinned
                y.col(i).setZero();
                continue;
            }
            const Vec3 xi = x.col(i);
            Vec3 yi = mass_[i] * xi;
            for (int e = adjStart_[static_cast<size_t>(i)]; e < adjStart_[static_cast<size_t>(i) + 1]; ++e) {
                const SpringEnd& end = adj_[static_cast<size_t>(e)];
                const SpringBlock& B = B_[static_cast<size_t>(end.spring)];
                const Vec3 u = xi - x.col(end.other);
                yi += (B.a * B.n.dot(u)) * B.n + B.b * u;
            }
            y.col(i) = yi;
        }
    });
}

bool ImplicitEulerSolver::stepBlockCg(Matrix3X& x, Matrix3X& v, const VectorX& w, const std::vector<Spring>& springs,
                                      double c, double dt) {
    auto unit = team_.unit();  // the threads of this step: solver.threads, or timed (AdaptiveTeam)
    const int n = static_cast<int>(x.cols());
    // (2) per spring its block B = −Δt² K_jj − Δt D_jj and Δt² K_jj (v_j − v_i), each spring on its own (no race).
    // K_jj and D_jj as in springJacobianBlocks(), kept as n and two numbers: −Δt² K_jj = aK n nᵀ + bK I.
    const int m = static_cast<int>(springs.size());
    forEachShare(m, threads_, kParallelGroup, [&](int first, int last) {
        for (int k = first; k < last; ++k) {
            const Spring& s = springs[static_cast<size_t>(k)];
            SpringBlock& B = B_[static_cast<size_t>(k)];
            const Vec3 d = x.col(s.j) - x.col(s.i);
            const double l = d.norm();
            if (!(l > 1e-12)) {  // no direction: no stiffness
                B = {Vec3::Zero(), 0.0, 0.0};
                Kv_[static_cast<size_t>(k)].setZero();
                continue;
            }
            B.n = d / l;
            const double transverse = std::max(0.0, 1.0 - s.l0 / l);  // clamped: never indefinite
            const double aK = dt * dt * s.k * (1.0 - transverse), bK = dt * dt * s.k * transverse;
            B.a = aK + dt * s.kd;  // −Δt² K_jj − Δt D_jj, D_jj = −k_d n nᵀ
            B.b = bK;
            const Vec3 u = v.col(s.j) - v.col(s.i);
            Kv_[static_cast<size_t>(k)] = -(aK * B.n.dot(u) * B.n + bK * u);
        }
    });
    // b_i = Δt f_i ± (K v) of its springs; the block-Jacobi preconditioner D_i⁻¹, D_i = (m_i + Δt c) I + Σ B_s; per particle
    bBlock_.resize(3, n);
    forEachShare(n, threads_, kParallelGroup, [&](int first, int last) {
        for (int i = first; i < last; ++i) {
            if (!(w[i] > 0.0)) {
                bBlock_.col(i).setZero();
                mass_[i] = 0.0;
                Dinv_[static_cast<size_t>(i)].setZero();  // keeps z, and so Δv, zero there
                continue;
            }
            mass_[i] = 1.0 / w[i] + dt * c;
            Vec3 bi = dt * f_.col(i);
            Mat3 D = mass_[i] * Mat3::Identity();
            for (int e = adjStart_[static_cast<size_t>(i)]; e < adjStart_[static_cast<size_t>(i) + 1]; ++e) {
                const size_t k = static_cast<size_t>(adj_[static_cast<size_t>(e)].spring);
                const SpringBlock& B = B_[k];
                bi += springs[k].j == i ? Kv_[k] : Vec3(-Kv_[k]);
                D += B.a * B.n * B.n.transpose() + B.b * Mat3::Identity();
            }
            bBlock_.col(i) = bi;
            Dinv_[static_cast<size_t>(i)] = D.inverse();
        }
    });
    // (3) preconditioned conjugate gradients from the previous step's Δv (pinned columns stay zero)
    const auto precondition = [&](const Matrix3X& r, Matrix3X& z) {
        forEachShare(n, threads_, kParallelGroup, [&](int first, int last) {
            for (int i = first; i < last; ++i) z.col(i) = Dinv_[static_cast<size_t>(i)] * r.col(i);
        });
    };
    Matrix3X& dv = dvBlock_;
    for (int i = 0; i < n; ++i)
        if (!(w[i] > 0.0)) dv.col(i).setZero();
    Matrix3X r(3, n), z(3, n), p(3, n), Ap(3, n);
    applyA(dv, Ap);
    r = bBlock_ - Ap;
    const double bb = dot(bBlock_, bBlock_, threads_);
    const double goal = kTolerance * kTolerance * bb;
    precondition(r, z);
    p = z;
    double rz = dot(r, z, threads_), rr = dot(r, r, threads_);
    iterations_ = 0;
    for (const int maxIterations = 6 * n; rr > goal && iterations_ < maxIterations; ++iterations_) {
        applyA(p, Ap);
        const double alpha = rz / dot(p, Ap, threads_);
        dv += alpha * p;
        r -= alpha * Ap;
        rr = dot(r, r, threads_);
        precondition(r, z);
        const double rzNew = dot(r, z, threads_);
        p = z + (rzNew / rz) * p;
        rz = rzNew;
    }
    if (!dv.allFinite()) return false;
    // Momentum: the springs' blocks cancel in Σ_i (A Δv)_i, so the momentum the step adds is Σ_i b_i
    // − Σ_i r_i, off by the residual's sum. Shifting every Δv_i by δ = Σ r_i / Σ (m_i + Δt c) removes
    // it (a uniform shift stretches no spring between free particles): internal forces then conserve
    // momentum exactly, as with the exact solve.
    applyA(dv, Ap);
    r = bBlock_ - Ap;
    Vec3 rSum = Vec3::Zero();
    double mSum = 0.0;
    for (int i = 0; i < n; ++i)
        if (w[i] > 0.0) rSum += r.col(i), mSum += 1.0 / w[i] + dt * c;
    for (int i = 0; i < n; ++i)
        if (w[i] > 0.0) dv.col(i) += rSum / mSum;
    applyA(dv, Ap);  // the true residual, not the recurrence's
    r = bBlock_ - Ap;
    residual_ = bb > 0.0 ? std::sqrt(dot(r, r, threads_) / bb) : 0.0;

    // (4) v += Δv, x += Δt v (pinned particles keep their velocity: their Δv is zero)
    v += dv;
    x += dt * v;
    return true;
}

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
    // A block column's three rows are consecutive in the column (the pattern has whole 3x3 blocks).
    const auto column = [&](int row, int col) { return row >= 0 && col >= 0 ? offset(row, col) : -1; };
    blocks_.assign(springs.size(), {});
    for (size_t k = 0; k < springs.size(); ++k) {
        const int a = index_[static_cast<size_t>(springs[k].i)], b = index_[static_cast<size_t>(springs[k].j)];
        for (int c = 0; c < 3; ++c) {
            blocks_[k][c] = column(a, a < 0 ? -1 : a + c);
            blocks_[k][3 + c] = column(b, b < 0 ? -1 : b + c);
            blocks_[k][6 + c] = column(a, b < 0 ? -1 : b + c);
            blocks_[k][9 + c] = column(b, a < 0 ? -1 : a + c);
        }
    }
    pattern_springs_ = springs.size();
    used_ = solve_ != ImplicitSolve::Auto ? solve_ : unknowns > kCholeskyMaxUnknowns ? ImplicitSolve::BlockCg : ImplicitSolve::Cholesky;
    if (used_ == ImplicitSolve::BlockCg) buildBlocks(w, springs);
    dv_ = VectorX::Zero(unknowns);
    if (used_ == ImplicitSolve::Cholesky) ldlt_.analyzePattern(A_);
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
    if (used_ == ImplicitSolve::BlockCg) return stepBlockCg(x, v, w, springs, c, dt);
    b_.resize(unknowns);
    for (int i = 0; i < n; ++i)
        if (const int r = index_[static_cast<size_t>(i)]; r >= 0) b_.segment<3>(r) = dt * f_.col(i);

    // (2) A = M - dt D - dt² K (global damping: D_ii = -c I), and b += dt² K v, one 3x3 block at a time
    double* A = A_.valuePtr();
    std::fill(A, A + A_.nonZeros(), 0.0);
    for (int i = 0; i < n; ++i)
        if (const int r = index_[static_cast<size_t>(i)]; r >= 0)
            for (int k = 0; k < 3; ++k) A[diag_[static_cast<size_t>(r + k)]] = 1.0 / w[i] + dt * c;
    // A's block at the offsets o[0..2] (one per column) += sign · B
    const auto addBlock = [A](const int* o, double sign, const Mat3& B) {
        if (o[0] < 0) return;
        for (int col = 0; col < 3; ++col) Eigen::Map<Vec3>(A + o[col]) += sign * B.col(col);
    };
    Mat3 Kjj, Djj;
    for (size_t k = 0; k < springs.size(); ++k) {
        const Spring& s = springs[k];
        const int a = index_[static_cast<size_t>(s.i)], b = index_[static_cast<size_t>(s.j)];
        if (a < 0 && b < 0) continue;
        springJacobianBlocks(s, x, Kjj, Djj);
        const Mat3 B = -dt * dt * Kjj - dt * Djj;  // block of A at (a, a) and (b, b); −B at (a, b) and (b, a)
        const int* o = blocks_[k].data();
        addBlock(o, 1.0, B);
        addBlock(o + 3, 1.0, B);
        addBlock(o + 6, -1.0, B);
        addBlock(o + 9, -1.0, B);
        const Vec3 Kv = dt * dt * Kjj * (v.col(s.j) - v.col(s.i));  // (K v)_j = Kjj (v_j − v_i), (K v)_i = −(K v)_j
        if (b >= 0) b_.segment<3>(b) += Kv;
        if (a >= 0) b_.segment<3>(a) -= Kv;
    }

    // (3) solve A Δv = b: sparse Cholesky, the pattern analysed once (large systems: stepBlockCg above)
    iterations_ = 0;
    ldlt_.factorize(A_);
    if (ldlt_.info() != Eigen::Success) return false;
    dv_ = ldlt_.solve(b_);
    if (ldlt_.info() != Eigen::Success || !dv_.allFinite()) return false;
    const double bNorm = b_.norm();
    residual_ = bNorm > 0.0 ? (b_ - A_ * dv_).norm() / bNorm : 0.0;
    const VectorX& dv = dv_;

    // (4) v += Δv, x += dt v (pinned particles keep their velocity)
    for (int i = 0; i < n; ++i)
        if (const int r = index_[static_cast<size_t>(i)]; r >= 0) v.col(i) += dv.segment<3>(r);
    x += dt * v;
    return true;
}

}  // namespace clothlab
