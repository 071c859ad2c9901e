/// @file bending_batched.h
/// @brief A fast bending sweep for the reference demos and benchmarks (instructor copy only).
///
/// The solver's default bending sweep calls exercise 5.2, projectBendingConstraint(), once per
/// stencil. This file does the same projections, in the same order, several stencils at a time with the
/// CPU's vector instructions: the solver option `solver.kernel: "batched"`. It is a
/// solved stage 05, so `./lab release` leaves it out (it lives in solutions/kernels/).
///
/// The formulas are those of exercise 5.2 rewritten so that a projection needs one square root
/// and one division. With positions relative to p1, \f$\vec a=\vec p_2-\vec p_1\f$ (the shared edge),
/// \f$\vec b=\vec p_3-\vec p_1\f$, \f$\vec c=\vec p_4-\vec p_1\f$, the unnormalised normals
/// \f$\vec m_1=\vec a\times\vec b\f$, \f$\vec m_2=\vec a\times\vec c\f$
/// (\f$L_1=|\vec m_1|^2\f$, \f$L_2=|\vec m_2|^2\f$, \f$D=\vec m_1\cdot\vec m_2\f$, \f$A=|\vec a|^2\f$)
/// and \f$V=\vec a\cdot(\vec b\times\vec c)\f$:
/// \f[ \varphi=\arccos(\vec n_1\cdot\vec n_2)=\operatorname{atan2}(S, D),\qquad
///     S=|\vec m_1\times\vec m_2|=|V|\,|\vec a|. \f]
/// The gradient of φ is the hinge's (Bridson et al., "Simulation of clothing with folds and wrinkles",
/// 2003): the wing vertices move along their triangle's normal, \f$\nabla_3\varphi=-s\,|\vec a|\,\vec m_1/L_1\f$
/// and \f$\nabla_4\varphi=s\,|\vec a|\,\vec m_2/L_2\f$ (s = sign V), and the edge's ends share what keeps
/// the momentum and the angular momentum, split at the wings' feet on the edge
/// (\f$t_3=\vec a\cdot\vec b/A\f$, \f$t_4=\vec a\cdot\vec c/A\f$):
/// \f$\nabla_1\varphi=-(1-t_3)\nabla_3\varphi-(1-t_4)\nabla_4\varphi\f$,
/// \f$\nabla_2\varphi=-t_3\nabla_3\varphi-t_4\nabla_4\varphi\f$. Times \f$\sigma=L_1L_2|\vec a|\f$ and s
/// they need no division:
/// \f[ \vec G_3=-A\,L_2\vec m_1,\quad \vec G_4=A\,L_1\vec m_2,\quad
///     \vec G_2=(\vec a\cdot\vec b)\,L_2\vec m_1-(\vec a\cdot\vec c)\,L_1\vec m_2,\quad \vec G_1=-\vec G_2-\vec G_3-\vec G_4, \f]
/// \f$\nabla_i\varphi=s\,\vec G_i/\sigma\f$, and the correction of exercise 5.2
/// (\f$\Delta\vec p_i=-k\,C\,w_i\nabla_iC/\sum_j w_j|\nabla_jC|^2\f$, C = φ − φ0) becomes
/// \f[ \Delta\vec p_i=f\,w_i\vec G_i,\qquad f=-s\,\frac{k\,(\varphi-\varphi_0)\,\sigma}{\sum_j w_j|\vec G_j|^2}. \f]
/// XPBD (projectBendingXpbd() in sim/xpbd.h) moves along the same vectors:
/// \f[ f=-s\,\frac{(\varphi-\varphi_0+\tilde\alpha\lambda)\,\sigma}{\sum_j w_j|\vec G_j|^2+\tilde\alpha\,\sigma^2},
///     \qquad \Delta\lambda=s\,f\,\sigma, \f]
/// which is the PBD correction with k = 1 for \f$\tilde\alpha = 0\f$. The cases without a correction are
/// exercise 5.2's: a zero-area triangle (\f$L_i<10^{-24}\f$), flat or folded
/// (\f$\sin^2\varphi=S^2/(L_1L_2)<10^{-12}\f$), all pinned (exercise 5.1's q-vectors are
/// \f$\vec q_i=-\sin\varphi\,\nabla_i\varphi\f$, so \f$\sum_j w_j|\vec q_j|^2=\sin^2\varphi\sum_j w_j|\vec G_j|^2/\sigma^2<10^{-24}\f$).
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
