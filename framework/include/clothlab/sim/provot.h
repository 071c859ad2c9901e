/// @file provot.h
/// @brief Provot's deformation constraint (Provot 1995): a cure for super-elasticity.
///
/// Stiff springs would keep a cloth from stretching, but explicit integrators cannot take them
/// (k_crit ≈ m π² / Δt²). Provot keeps soft springs and, after each time step, shortens every spring
/// whose strain exceeds a critical value τ by moving its end points back along the spring.
#pragma once
#include <vector>

#include "clothlab/core/spring.h"
#include "clothlab/core/types.h"

namespace clothlab {

/// Shortens over-stretched springs after a time step (Provot's deformation constraint).
///
/// For every spring with length \f$ l > (1+\tau)\,l_0 \f$ the end points move along
/// \f$ \hat d = (\vec x_j - \vec x_i)/l \f$ by the excess \f$ \delta = l - (1+\tau)\,l_0 \f$, shared by their
/// inverse masses: \f[ \Delta\vec x_i = \frac{w_i}{w_i+w_j}\,\delta\,\hat d,\qquad
/// \Delta\vec x_j = -\frac{w_j}{w_i+w_j}\,\delta\,\hat d \f]
/// (equal masses: half each; a pinned end, w = 0, stays put and the other end moves the whole way;
/// both pinned: nothing moves). The velocities get the same correction divided by Δt,
/// \f$ \vec v \mathrel{+}= \Delta\vec x / \Delta t \f$, so that the removed stretch does not come back
/// in the next step. Correcting one spring can stretch its neighbours, so the passes over all springs
/// repeat (Gauss–Seidel) until no spring exceeds \f$ (1+\tau)\,l_0 \f$ by more than a relative 10⁻⁶
/// or `max_passes` (default 50) passes are made. (A pass skips the springs whose end points no
/// correction has moved since they were found within the limit: they still are, so the corrections and
/// the number of passes are those of full passes, bit for bit.) On scenes/mfn_provot.json (τ = 0.1) the 50 passes
/// keep max_strain at most 0.0002 above τ (largest 0.10017 over the run, 0.100001 at its end; docs/mfn.md).
/// @param springs     the springs (those with l0 = 0 are left alone)
/// @param x           positions, 3 x N, m (corrected in place)
/// @param v           velocities, 3 x N, m/s (corrected in place)
/// @param w           inverse masses, N, 1/kg
/// @param tau         critical strain τ > 0 (0.1 = 10 %)
/// @param dt          the time step Δt, s
/// @param max_passes  upper bound on the number of passes over all springs
/// @return            number of passes made
int applyProvotConstraint(const std::vector<Spring>& springs, Matrix3X& x, Matrix3X& v, const VectorX& w, double tau,
                          double dt, int max_passes = 50);

}  // namespace clothlab
