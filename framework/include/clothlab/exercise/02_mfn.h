/// @file 02_mfn.h
/// @brief Stage 02 (Masse-Feder-Netzwerke, MFN): cloth as a mass-spring network.
///
/// The student writes these functions in `exercises/02_mfn/mfn.cpp`;
/// the task sheet is `exercises/02_mfn/README.md`. Notation as on the slides:
/// x positions (3 x N, m), v velocities (3 x N, m/s), w inverse masses (N, 1/kg; w = 0: pinned),
/// k Federhärte (stiffness, N/m), l0 Ruhelänge (rest length, m).
///
/// The cloth is a grid of nx x ny particles (Massepartikel auf einem Gitter); particle (c, r)
/// in column c and row r has index i = r·nx + c (see gridIndex()). The particles themselves
/// (positions, masses with \f$ m_{gesamt} = \sum_i m_i \f$, pins) come from makeGridState().
#pragma once
#include <vector>

#include "clothlab/core/spring.h"
#include "clothlab/core/types.h"

namespace clothlab {

/// Exercise 2.1 — the springs of a cloth grid (Strukturfedern, Scherfedern, Biegefedern).
///
/// For every particle (c, r), with i = r·nx + c:
/// - structural (Strukturfedern): to (c+1, r) and to (c, r+1);
/// - shear (Scherfedern): to (c+1, r+1) and from (c+1, r) to (c, r+1) — both diagonals of each cell;
/// - bending (Biegefedern): to (c+2, r) and to (c, r+2).
///
/// Only neighbours inside the grid get a spring, every pair at most once, and only the types
/// whose group is enabled. Each spring records its kind in Spring::type (Structural, Shear or
/// Bending, never the default Single), takes k and kd from that type's group, and its rest length
/// from the initial positions: \f$ l_0 = \|\vec x_j - \vec x_i\| \f$. The counts are
/// \f$ (n_x-1)n_y + n_x(n_y-1) \f$ structural, \f$ 2(n_x-1)(n_y-1) \f$ shear and
/// \f$ (n_x-2)n_y + n_x(n_y-2) \f$ bending springs (terms with a negative factor count as 0).
/// @param x       initial positions, 3 x (nx·ny), m; particle (c, r) is column r·nx + c
/// @param nx, ny  grid size, particles per row and per column (≥ 2 each)
/// @param types   which spring types exist and their stiffness k (N/m) and damping kd (N s/m)
/// @return        the springs; Spring::i < Spring::j is not required
std::vector<Spring> makeClothSprings(const Matrix3X& x, int nx, int ny, const ClothSprings& types);

/// Exercise 2.2 — add the forces of all springs (Federkräfte) to f.
///
/// Each spring s = (i, j, k, l0, kd) is a Hooke spring with damping along it, as in stage 01:
/// use hookeForce() and springDampingForce() with x_i, v_i as their first and x_j, v_j as their
/// second end point. Requirements: each particle receives the force its springs exert on *it*
/// (mind which end stage 01's functions return the force for); actio = reactio, so the spring forces
/// of the whole cloth sum to zero; the total is minus the gradient of the sum of the spring energies;
/// coincident particles (|x_i − x_j| < 1e-12 m, degenerate: notation table) give no NaN.
/// @param springs  the springs, e.g. from makeClothSprings()
/// @param x        positions, 3 x N, m
/// @param v        velocities, 3 x N, m/s
/// @param f        forces, 3 x N, N; the spring forces are added (not overwritten)
void addClothSpringForces(const std::vector<Spring>& springs, const Matrix3X& x, const Matrix3X& v, Matrix3X& f);

/// Exercise 2.3 — add gravity (Schwerkraft) and air damping (Dämpfung) to f.
///
/// Every free particle i gets its weight (its mass \f$ m_i = 1/w_i \f$ in the field g) and an air
/// drag that opposes its velocity, linear in \f$ \vec v_i \f$ with coefficient c (1 m/s gives c newtons).
/// Pinned particles (w_i = 0, infinite mass) get neither: their force stays as it is (never Inf or NaN).
/// Over a cloth without pins the gravity forces sum to \f$ m_{gesamt}\,\vec g \f$, in whatever
/// direction g points.
/// @param w  inverse masses, N, 1/kg
/// @param v  velocities, 3 x N, m/s
/// @param g  gravitational acceleration, m/s² (e.g. (0, −9.81, 0))
/// @param c  damping coefficient, N s/m (c ≥ 0; 0: no damping)
/// @param f  forces, 3 x N, N; added to
void addClothExternalForces(const VectorX& w, const Matrix3X& v, const Vec3& g, double c, Matrix3X& f);

}  // namespace clothlab
