/// @file bending_batched.h
/// @brief A fast bending sweep for the reference demos and benchmarks (instructor copy only).
///
/// The solver's default bending sweep calls exercise 5.2, projectBendingConstraint(), once per
/// stencil. This file does the same projections, in the same order, several stencils at a time with the
/// CPU's vector instructions: the solver option `solver.kernel: "batched"`. It is a
/// solved stage 05, so `./lab release` leaves it out (it lives in solutions/kernels/).
///
/// The formulas are those of exercise 5.2 rewritten so that a projection needs one square root
/// and two divisions. With positions relative to p1, \f$\vec a=\vec p_2-\vec p_1\f$,
/// \f$\vec b=\vec p_3-\vec p_1\f$, \f$\vec c=\vec p_4-\vec p_1\f$ and the unnormalised normals
/// \f$\vec m_1=\vec a\times\vec b\f$, \f$\vec m_2=\vec a\times\vec c\f$
/// (\f$L_1=|\vec m_1|^2\f$, \f$L_2=|\vec m_2|^2\f$, \f$D=\vec m_1\cdot\vec m_2\f$):
/// \f[ \varphi=\arccos(\vec n_1\cdot\vec n_2)=\operatorname{atan2}(S, D),\qquad
///     S=|\vec m_1\times\vec m_2|=|\vec a\cdot(\vec b\times\vec c)|\,|\vec a| \f]
/// and with \f$\vec E_1=L_1\vec m_2-D\,\vec m_1\f$, \f$\vec E_2=L_2\vec m_1-D\,\vec m_2\f$ the
/// q-vectors of exercise 5.1 are \f$\vec q_i=\vec Q_i/(L_1L_2)^{3/2}\f$ with
/// \f[ \vec Q_3=L_2\,\vec E_1\times\vec a,\quad \vec Q_4=L_1\,\vec E_2\times\vec a,\quad
///     \vec Q_2=L_2\,\vec b\times\vec E_1+L_1\,\vec c\times\vec E_2,\quad \vec Q_1=-\vec Q_2-\vec Q_3-\vec Q_4 \f]
/// so that the correction of exercise 5.2 becomes
/// \f[ \Delta\vec p_i=k\,(\varphi-\varphi_0)\,\frac{L_1L_2\,S}{\sum_j w_j|\vec Q_j|^2}\,w_i\vec Q_i. \f]
/// XPBD (projectBendingXpbd() in sim/xpbd.h) moves along the same vectors: with
/// \f$\nabla_i C=-\vec q_i/\sin\varphi\f$ and \f$\sum_j w_j|\nabla_j C|^2=\sum_j w_j|\vec Q_j|^2/(L_1L_2S)^2\f$,
/// \f[ \Delta\vec p_i=f\,w_i\vec Q_i,\qquad f=\frac{(\varphi-\varphi_0+\tilde\alpha\lambda)\,L_1L_2S}{\sum_j w_j|\vec Q_j|^2+\tilde\alpha\,(L_1L_2S)^2},
///     \qquad \Delta\lambda=-f\,L_1L_2S, \f]
/// which is the PBD correction with k = 1 for \f$\tilde\alpha = 0\f$.
#pragma once
#include <vector>

#include "clothlab/core/types.h"
#include "clothlab/exercise/05_bending.h"
#include "clothlab/sim/sweeps.h"

namespace clothlab {

/// The bending stencils in structure-of-arrays form, cut into blocks of stencils that share no
/// particle (so the stencils of a block can be projected at the same time).
struct BendingBlocks {
    std::vector<int> i1;              ///< particle i1 of each stencil (as in BendingStencil), one per stencil
    std::vector<int> i2;              ///< particle i2 of each stencil
    std::vector<int> i3;              ///< particle i3 of each stencil
    std::vector<int> i4;              ///< particle i4 of each stencil
    std::vector<double> phi0;         ///< rest angle φ0 of each stencil, rad
    std::vector<int> start;           ///< block b holds stencils start[b] .. start[b+1] − 1 (one more entry than blocks)
    /// Colour group g holds blocks groups[g] .. groups[g+1] − 1: the blocks of a group share no
    /// particle and are projected in parallel.
    std::vector<int> groups;
    int threads = 1;                  ///< threads per colour group (1: serial)
};

/// Largest number of stencils in one block (the vector loop's width: 8 doubles × 2).
constexpr int kBendingBlockSize = 16;

/// Cuts the stencils, kept in their order, into blocks: a stencil starts a new block when it shares a
/// particle with a stencil of the current block, when the block holds kBendingBlockSize stencils or
/// when a colour group of the plan starts. In the solver's colour order (colourOrder()) almost every
/// block is full.
/// @param stencils  the stencils in the order the sweep projects them
/// @param plan      their colour groups and threads (sweepPlan()); default: one group, serial
/// @return          the same stencils as blocks; projecting block by block equals projecting one by one
BendingBlocks bendingBlocks(const std::vector<BendingStencil>& stencils, const SweepPlan& plan = {});

/// Which vector loop projectBendingBlocks() runs.
enum class BendingLoop {
    Best,    ///< AVX-512 gather/scatter where the CPU has it, else Staged
    Staged,  ///< the loop without scatter instructions (AVX2, plain x86-64, other CPUs); forced for tests
};

/// One Gauss–Seidel sweep over the stencils, colour group by colour group, the blocks of a group in
/// parallel (blocks.threads; bit-identical for every number of threads): the same result as projectBendingSweep()
/// with the reference exercise 5.2 up to rounding (closer to exact near flat), with the correction in
/// the form of this file's header. No correction (never NaN) in the cases where exercise 5.2 gives
/// none: a zero-area triangle (L_1 or L_2 below 1e-24 m⁴), flat or folded
/// (\f$S^2<10^{-12}L_1L_2\f$, i.e. 1 − d² < 1e-12), all pinned (\f$\sum_j w_j|\vec q_j|^2<10^{-24}\f$).
/// @param blocks  the stencils, from bendingBlocks()
/// @param w       inverse masses, length N, 1/kg
/// @param k       per-iteration stiffness k' in [0, 1]
/// @param p       predicted positions, 3 x N, m (updated in place)
/// @param loop    BendingLoop::Best, or Staged to test that loop on a CPU with AVX-512
void projectBendingBlocks(const BendingBlocks& blocks, const VectorX& w, double k, Matrix3X& p,
                          BendingLoop loop = BendingLoop::Best);

/// One XPBD sweep over the stencils, in the order and with the threads of projectBendingBlocks(): the
/// same result as projectBendingSweepXpbd() (sim/sweeps.h) up to rounding, with the correction of this
/// file's header; no correction where projectBendingBlocks() gives none.
/// @param blocks      the stencils, from bendingBlocks()
/// @param w           inverse masses, length N, 1/kg
/// @param alphaTilde  compliance of the angle over the squared (sub)step, α/Δt²
/// @param lambda      one multiplier λ per stencil in the order of bendingBlocks()' input, updated
/// @param p           predicted positions, 3 x N, m (updated in place)
/// @param loop        BendingLoop::Best, or Staged to test that loop on a CPU with AVX-512
void projectBendingBlocksXpbd(const BendingBlocks& blocks, const VectorX& w, double alphaTilde,
                              std::vector<double>& lambda, Matrix3X& p, BendingLoop loop = BendingLoop::Best);

/// Whether BendingLoop::Best uses AVX-512 gather/scatter on this CPU (x86-64-v4, built with GCC ≥ 12
/// for glibc) or the staged loop.
/// @return  true when the AVX-512 sweep runs
bool bendingBlocksUseScatter();

/// The angle atan2(y, x) ∈ [0, π] for y ≥ 0 as the kernel computes it, without a library call:
/// reduced to θ ∈ [0, π/4] (the octant), then to |t| ≤ tan(π/16) by the nearest shift σ of 0, π/8,
/// π/4 (\f$\arctan u-\sigma=\arctan\frac{u-\tan\sigma}{1+u\tan\sigma}\f$, one division), then
/// \f$\arctan t=\sum_{n=0}^{11}(-1)^n\frac{t^{2n+1}}{2n+1}\f$ (truncation error below 1e-19).
/// @param y  the sine side, y ≥ 0
/// @param x  the cosine side
/// @return   the angle, rad (NaN for y = x = 0)
double atan2Upper(double y, double x);

}  // namespace clothlab
