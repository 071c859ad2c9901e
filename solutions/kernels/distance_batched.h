/// @file distance_batched.h
/// @brief A fast distance sweep for the reference demos and benchmarks (instructor copy only).
///
/// The solver's default distance sweep calls exercise 4.3, projectDistanceConstraint(), once per
/// link: a function call per link, which the compiler cannot inline (the stage's code is compiled
/// apart). This file does the same projections, in the same order, with the formula in the loop
/// (`solver.kernel: "batched"`): the links of a colour group share no particle, so the loop runs
/// several of them at a time in the CPU's vector registers. It is a solved stage 04, so
/// `./lab release` leaves it out (it lives in solutions/kernels/).
///
/// With \f$\vec e=\vec p_i-\vec p_j\f$, \f$\ell=|\vec e|\f$, \f$C=\ell-d\f$ and \f$W=w_i+w_j\f$ one
/// projection is
/// \f[ \Delta\vec p_i=-w_i\,f\,\vec e,\qquad \Delta\vec p_j=w_j\,f\,\vec e,\qquad
///     f=\frac{k\,C+\tilde\alpha\lambda}{(W+\tilde\alpha)\,\ell},\qquad \Delta\lambda=-f\,\ell, \f]
/// PBD for α̃ = 0 (exercise 4.3 with stiffness k) and XPBD for k = 1 (projectDistanceXpbd() in sim/xpbd.h).
#pragma once
#include <vector>

#include "clothlab/core/types.h"
#include "clothlab/sim/sweeps.h"

namespace clothlab {

/// The links in structure-of-arrays form with the colour groups they are swept in.
struct DistanceArrays {
    std::vector<int> i;          ///< first particle of each link
    std::vector<int> j;          ///< second particle of each link
    std::vector<double> d;       ///< rest length of each link, m
    /// Colour group g holds links groups[g] .. groups[g+1] − 1; they share no particle.
    std::vector<int> groups;
    int threads = 1;             ///< threads per colour group (1: serial)
};

/// The links in their order, with the plan's colour groups; without a plan (no groups), groups of
/// consecutive links that share no particle, so that the sweep equals projecting one link after the other.
/// @param links  the links in the order the sweep projects them
/// @param plan   their colour groups and threads (sweepPlan()); default: one serial sweep in list order
/// @return       the links as arrays
DistanceArrays distanceArrays(const std::vector<DistanceLink>& links, const SweepPlan& plan = {});

/// One Gauss–Seidel PBD sweep over the links with the formula of this file's header (α̃ = 0): the same
/// result as projectDistanceSweep() with the reference exercise 4.3 up to rounding, bit-identical for
/// every number of threads. No correction (never NaN) where exercise 4.3 gives none: coincident points
/// (ℓ < 1e-12 m) or both pinned (W = 0).
/// @param links  the links, from distanceArrays()
/// @param w      inverse masses, length N, 1/kg
/// @param k      per-iteration stiffness k' in [0, 1]
/// @param p      predicted positions, 3 x N, m (updated in place)
void projectDistanceArrays(const DistanceArrays& links, const VectorX& w, double k, Matrix3X& p);

/// One XPBD sweep over the links (k = 1): the same result as projectDistanceSweepXpbd() up to rounding.
/// @param links       the links, from distanceArrays()
/// @param w           inverse masses, length N, 1/kg
/// @param alphaTilde  compliance over the squared (sub)step, α/Δt², kg⁻¹
/// @param lambda      one multiplier λ per link in the links' order, kg m, updated
/// @param p           predicted positions, 3 x N, m (updated in place)
void projectDistanceArraysXpbd(const DistanceArrays& links, const VectorX& w, double alphaTilde,
                               std::vector<double>& lambda, Matrix3X& p);

}  // namespace clothlab
