/// @file sweeps.h
/// @brief One Gauss–Seidel sweep over all constraints of one type: line (10) of the PBD loop,
/// projectConstraints(C_1, ..., C_M, p_1, ..., p_N), split by constraint type.
///
/// Each sweep visits its constraints in the given order and moves p in place right after each
/// projection (Gauss–Seidel). The projections are the stage functions (the student's or the
/// reference code): exercise 4.3 (distance), 5.2 (bending), 6.3 (collision), 7.5 and 7.6
/// (self-collision), or their XPBD forms in xpbd.h.
#pragma once
#include <vector>

#include "clothlab/exercise/05_bending.h"
#include "clothlab/exercise/06_collision.h"
#include "clothlab/exercise/07_self_collision.h"

namespace clothlab {

/// A distance constraint between particles i and j with rest length d (an edge of the cloth).
struct DistanceLink {
    int i = 0;        ///< first particle
    int j = 0;        ///< second particle
    double d = 0.0;   ///< rest length, m
};

/// PBD distance sweep: for every link, \f$ \vec p_i \mathrel{+}= \Delta\vec p_1,\ \vec p_j \mathrel{+}= \Delta\vec p_2 \f$
/// with the corrections of projectDistanceConstraint() (exercise 4.3).
/// @param links  the constraints, in the order they are projected
/// @param w      inverse masses, length N, 1/kg
/// @param k      per-iteration stiffness k' in [0, 1]
/// @param p      predicted positions, 3 x N, m (updated in place)
void projectDistanceSweep(const std::vector<DistanceLink>& links, const VectorX& w, double k, Matrix3X& p);

/// PBD bending sweep: for every stencil, \f$ \vec p_{i_m} \mathrel{+}= \Delta\vec p_m \f$ (m = 1..4) with the
/// corrections of projectBendingConstraint() (exercise 5.2).
/// @param stencils  the constraints with their rest angles φ0, in the order they are projected
/// @param w         inverse masses, length N, 1/kg
/// @param k         per-iteration stiffness k' in [0, 1]
/// @param p         predicted positions, 3 x N, m (updated in place)
void projectBendingSweep(const std::vector<BendingStencil>& stencils, const VectorX& w, double k, Matrix3X& p);

/// XPBD distance sweep: projectDistanceXpbd() for every link, \f$ \tilde\alpha = \alpha/\Delta t^2 \f$.
/// @param links       the constraints, in the order they are projected
/// @param w           inverse masses, length N, 1/kg
/// @param alphaTilde  compliance over the squared (sub)step, α/Δt², kg⁻¹
/// @param lambda      one multiplier λ per link (kg m), updated; zero at the start of every (sub)step
/// @param p           predicted positions, 3 x N, m (updated in place)
void projectDistanceSweepXpbd(const std::vector<DistanceLink>& links, const VectorX& w, double alphaTilde,
                              std::vector<double>& lambda, Matrix3X& p);

/// XPBD bending sweep: projectBendingXpbd() for every stencil, \f$ \tilde\alpha = \alpha/\Delta t^2 \f$.
/// @param stencils    the constraints, in the order they are projected
/// @param w           inverse masses, length N, 1/kg
/// @param alphaTilde  compliance of the angle over the squared (sub)step, α/Δt²
/// @param lambda      one multiplier λ per stencil, updated; zero at the start of every (sub)step
/// @param p           predicted positions, 3 x N, m (updated in place)
void projectBendingSweepXpbd(const std::vector<BendingStencil>& stencils, const VectorX& w, double alphaTilde,
                             std::vector<double>& lambda, Matrix3X& p);

/// Collision sweep: \f$ \vec p_i \mathrel{+}= \f$ projectCollisionConstraint() (exercise 6.3) for every
/// collision constraint of this step.
/// @param contacts  the collision constraints made by line (8) in this step
/// @param w         inverse masses, length N, 1/kg
/// @param h         collision thickness h, m
/// @param p         predicted positions, 3 x N, m (updated in place)
void projectCollisionSweep(const std::vector<CollisionConstraint>& contacts, const VectorX& w, double h, Matrix3X& p);

/// Self-collision sweep: for every pair (i, j) with separation distance d (a DistanceLink read as the
/// inequality |p_i − p_j| ≥ d): the separation of projectSeparation() (exercise 7.5), then, with μ > 0,
/// the friction between the layers of layerFriction() (exercise 7.6) with the depth δ = d − |p_i − p_j|
/// the separation removed.
/// @param pairs  the pairs found at line (8) in this step, with d = h (pairs closer than h at rest left out)
/// @param x      positions at the start of the step, 3 x N, m
/// @param w      inverse masses, length N, 1/kg
/// @param mu     friction coefficient μ ≥ 0 between the layers
/// @param p      predicted positions, 3 x N, m (updated in place)
void projectSelfCollisionSweep(const std::vector<DistanceLink>& pairs, const Matrix3X& x, const VectorX& w, double mu,
                               Matrix3X& p);

}  // namespace clothlab
