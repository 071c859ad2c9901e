/// @file implicit_euler.h
/// @brief Linearised backward (implicit) Euler after Baraff & Witkin (1998): the stiff-case reference.
///
/// Backward Euler takes the forces at the END of the step,
/// \f$ v^{n+1} = v^n + \Delta t\,M^{-1} f(x^{n+1}, v^{n+1}) \f$, \f$ x^{n+1} = x^n + \Delta t\,v^{n+1} \f$.
/// Linearising f around the current state (one Newton step) gives one sparse linear system per step:
/// \f[ \Big(M - \Delta t\,\frac{\partial f}{\partial v} - \Delta t^2\,\frac{\partial f}{\partial x}\Big)\,\Delta v
///     = \Delta t\,\Big(f(x^n, v^n) + \Delta t\,\frac{\partial f}{\partial x}\,v^n\Big),\qquad
///     v^{n+1} = v^n + \Delta v,\quad x^{n+1} = x^n + \Delta t\,v^{n+1}. \f]
/// It is stable for every Δt on a linear spring system, at the price of artificial damping:
/// an undamped oscillation loses energy by the factor 1/(1 + ω²Δt²) per step.
#pragma once
#include <array>
#include <vector>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "clothlab/core/spring.h"
#include "clothlab/exercise/01_hooke.h"
#include "clothlab/sim/team.h"

namespace clothlab {

/// Sparse matrix type of the implicit solver (column-major, double).
using SparseMatrix = Eigen::SparseMatrix<double>;

/// The 3x3 Jacobian blocks of one spring (formulas at addSpringJacobians()): \f$ K_{jj} = \partial\vec f_j/\partial\vec x_j \f$
/// (N/m) and \f$ D_{jj} = \partial\vec f_j/\partial\vec v_j \f$ (N s/m); the other blocks are
/// \f$ K_{ii} = K_{jj} \f$, \f$ K_{ij} = K_{ji} = -K_{jj} \f$ and the same for D. Zero for a spring shorter than 10⁻¹² m.
/// @param s    the spring
/// @param x    positions, 3 x N, m
/// @param Kjj  set to ∂f_j/∂x_j, N/m
/// @param Djj  set to ∂f_j/∂v_j, N s/m
void springJacobianBlocks(const Spring& s, const Matrix3X& x, Eigen::Matrix3d& Kjj, Eigen::Matrix3d& Djj);

/// Adds the force Jacobians of the springs to triplet lists, 3x3 blocks per particle pair.
///
/// For a spring (i, j) with \f$ \vec d = \vec x_j - \vec x_i \f$, \f$ l = \|\vec d\| \f$, \f$ \hat n = \vec d/l \f$:
/// \f[ K_{jj} = \frac{\partial \vec f_j}{\partial \vec x_j} = -k\Big[\hat n\hat n^T + \max\big(0, 1 - \tfrac{l_0}{l}\big)\,(I - \hat n\hat n^T)\Big],
///     \qquad K_{ii} = K_{jj},\quad K_{ij} = K_{ji} = -K_{jj} \f]
/// (the transverse term is clamped at zero for compressed springs so that the system stays positive
/// definite, as in Choi & Ko 2002), and for the damping along the spring
/// \f$ D_{jj} = \partial \vec f_j / \partial \vec v_j = -k_d\,\hat n\hat n^T \f$, \f$ D_{ii} = D_{jj} \f$, \f$ D_{ij} = D_{ji} = -D_{jj} \f$.
/// A spring shorter than 10⁻¹² m has no direction: its blocks are zero (still listed, so that the
/// sparsity pattern never changes).
/// @param springs  the springs
/// @param x        positions, 3 x N, m
/// @param index    particle → first row of its 3 unknowns, or −1 for pinned particles (left out)
/// @param K        triplets of ∂f/∂x, N/m (appended to)
/// @param D        triplets of ∂f/∂v, N s/m (appended to)
void addSpringJacobians(const std::vector<Spring>& springs, const Matrix3X& x, const std::vector<int>& index,
                        std::vector<Eigen::Triplet<double>>& K, std::vector<Eigen::Triplet<double>>& D);

/// How ImplicitEulerSolver solves its linear system A Δv = b.
enum class ImplicitSolve {
    Auto,                  ///< Cholesky up to 300 unknowns, above BlockCg (the default)
    Cholesky,              ///< sparse LDLᵀ (Eigen::SimplicialLDLT), pattern analysed once, factorised every step
    /// Conjugate gradients on the 3x3 spring blocks without an assembled matrix: (A x)_i =
    /// (m_i + Δt c) x_i + Σ_s B_s (x_i − x_j) per particle, block-Jacobi preconditioner (the inverse
    /// 3x3 diagonal blocks), relative residual 10⁻³; particles in parallel (solver.threads), the
    /// same bits on any number of threads.
    BlockCg,
};

/// The linearised backward Euler stepper; keeps the factorisation's symbolic analysis between steps.
class ImplicitEulerSolver {
public:
    /// One step (formula in the file comment). Pinned particles (w = 0) keep their velocity and are
    /// left out of the system. The forces f(x, v) come from `force` (all force passes of the scene);
    /// the Jacobian from the springs and the global damping c (\f$ \partial f_i/\partial v_i \mathrel{+}= -c I \f$).
    /// The system matrix is symmetric positive definite, assembled in 3x3 blocks. Up to 300 unknowns
    /// (100 free particles) it is solved by a sparse Cholesky factorisation (Eigen::SimplicialLDLT:
    /// exact, robust for extreme stiffness and mass ratios; pattern analysed once); above, where the
    /// factor fills in and costs seconds per step, by conjugate gradients on the 3x3 blocks of the
    /// springs (ImplicitSolve::BlockCg), started from the previous step's Δv, until the relative
    /// residual \f$ |b - A\Delta v|/|b| \f$ is below 10⁻³. That is far below the step's own error: one
    /// linearised (Newton) step of a first-order method. If it does not converge within 2·unknowns
    /// iterations, the finite iterate is used.
    /// The sparsity pattern is rebuilt when particles are pinned or released.
    /// @param x, v     positions (m) and velocities (m/s), 3 x N (updated in place)
    /// @param w        inverse masses, N, 1/kg
    /// @param force    the force field F(x, v), N
    /// @param springs  the springs whose Jacobians enter the matrix
    /// @param c        global velocity damping, N s/m
    /// @param dt       time step Δt, s
    /// @return         false if the factorisation failed (the state is then left unchanged)
    bool step(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, const std::vector<Spring>& springs,
              double c, double dt);

    /// Chooses the linear solver (for benchmarks and tests; the default is ImplicitSolve::Auto).
    /// @param how  the solver of the following steps
    void setSolve(ImplicitSolve how) {
        solve_ = how;
        index_.clear();  // rebuild the pattern and the solver at the next step
    }
    /// Threads of the block solver: solver.threads N ≥ 1 fixes N, 0 takes the faster of one thread and
    /// defaultThreads(), timed per step (AdaptiveTeam, sim/team.h). The same bits either way.
    /// @param requested  solver.threads, ≥ 0
    void setThreads(int requested) {
        team_ = AdaptiveTeam(requested);
        threads_ = team_.most();
    }
    /// How many threads the block solver uses (setThreads()).
    const AdaptiveTeam& team() const { return team_; }
    /// The relative residual \f$ |b - A\Delta v|_2 / |b|_2 \f$ of the last step's solve (0 before the first).
    double residual() const { return residual_; }
    /// Conjugate-gradient iterations of the last step's solve (0 for Cholesky).
    int iterations() const { return iterations_; }

private:
    /// Builds the sparsity pattern of A (mass diagonal + one 3x3 block per spring end pair) and the
    /// offsets of every block column in A's value array, then analyses the pattern.
    void buildPattern(const VectorX& w, const std::vector<Spring>& springs);
    /// Offset of entry (r, c) in A_'s value array.
    int offset(int r, int c);
    /// Per particle the list of its springs, and the per-spring storage of BlockCg.
    void buildBlocks(const VectorX& w, const std::vector<Spring>& springs);
    /// y = A x with A from the spring blocks B_ and the masses mass_ (BlockCg); x, y 3 x N, zero at pinned particles.
    void applyA(const Matrix3X& x, Matrix3X& y) const;
    /// Steps (2)–(4) of step() with BlockCg; f_ holds the forces.
    bool stepBlockCg(Matrix3X& x, Matrix3X& v, const VectorX& w, const std::vector<Spring>& springs, double c, double dt);

    std::vector<int> index_;                   ///< particle → first unknown, −1 if pinned
    std::vector<int> diag_;                    ///< per unknown: offset of its diagonal entry in A_
    /// Per spring: for its blocks (a,a), (b,b), (a,b), (b,a) and each of their 3 columns, the offset
    /// of the column's first entry (the 3 entries of a block column are consecutive); −1 if absent.
    std::vector<std::array<int, 12>> blocks_;
    size_t pattern_springs_ = 0;               ///< number of springs the pattern was built for
    SparseMatrix A_;                           ///< the system matrix
    Eigen::SimplicialLDLT<SparseMatrix> ldlt_; ///< its factorisation (small systems)
    ImplicitSolve solve_ = ImplicitSolve::Auto; ///< as chosen
    ImplicitSolve used_ = ImplicitSolve::Cholesky; ///< what Auto resolved to for this pattern
    VectorX dv_;                               ///< Δv of the last step (CG's initial guess)
    Matrix3X f_;                               ///< forces at the start of the step
    VectorX b_;                                ///< right-hand side
    double residual_ = 0.0;                    ///< relative residual of the last solve
    int threads_ = 1;                          ///< the most threads of BlockCg
    AdaptiveTeam team_;                        ///< its threads per step: fixed, or the faster
    /// A spring's block of A, \f$ B = -\Delta t^2 K_{jj} - \Delta t D_{jj} = a\,\hat n\hat n^T + b\,I \f$ (kg).
    struct SpringBlock {
        Vec3 n{0, 0, 0};  ///< unit direction n̂ of the spring
        double a = 0.0;   ///< kg
        double b = 0.0;   ///< kg
    };
    /// One spring of a particle and the particle at its other end.
    struct SpringEnd {
        int spring = 0;   ///< index into the springs
        int other = 0;    ///< the particle at the other end
    };
    std::vector<int> adjStart_;                ///< BlockCg: the springs of particle i are adj_[adjStart_[i] .. adjStart_[i+1] − 1]
    std::vector<SpringEnd> adj_;               ///< BlockCg: per particle its springs and their other ends
    std::vector<SpringBlock> B_;               ///< BlockCg: per spring −Δt² K_jj − Δt D_jj
    VectorX mass_;                             ///< BlockCg: per particle m_i + Δt c, kg (0 if pinned)
    std::vector<Vec3> Kv_;                     ///< BlockCg: per spring Δt² K_jj (v_j − v_i)
    std::vector<Eigen::Matrix3d> Dinv_;        ///< BlockCg: per particle the inverse diagonal block of A
    Matrix3X bBlock_, dvBlock_;                ///< BlockCg: right-hand side and Δv, 3 x N (zero at pinned particles)
    int iterations_ = 0;                       ///< CG iterations of the last solve
};

}  // namespace clothlab
