/// @file grid.h
/// @brief The particles and triangles of a cloth: a regular grid (Massepartikel auf einem Gitter) or a mesh.
#pragma once
#include <vector>

#include <Eigen/Core>

#include "clothlab/core/scene.h"
#include "clothlab/core/state.h"

namespace clothlab {

/// Index of the particle in column c and row r of an nx-wide grid: r * nx + c.
inline int gridIndex(int c, int r, int nx) { return r * nx + c; }

/// Particles of a cloth at rest: positions on the grid, zero velocities, equal masses
/// \f$ m_i = m_{gesamt} / (n_x n_y) \f$ so that \f$ \sum_i m_i = m_{gesamt} \f$, and w = 0 for pinned particles.
/// Vertical cloth: x grows with the column, y falls with the row. Horizontal cloth: z grows with the row.
/// The whole grid is then turned by spec.rotation about the origin: x_i = origin + R (x_i⁰ − origin).
/// Pinned particles stay at rest here; movePins() moves them.
/// @param spec  grid size (nx, ny ≥ 2), extent (m), total mass (kg), origin, orientation, rotation, pins
/// @return      state with nx*ny particles
State makeGridState(const ClothSpec& spec);

/// Two triangles per grid cell, counter-clockwise seen from +z (vertical) or +y (horizontal),
/// split along the diagonal from (c, r) to (c+1, r+1).
/// @param nx, ny  grid size
/// @return        2 (nx-1)(ny-1) triangles as particle index triples
std::vector<Eigen::Vector3i> gridTriangles(int nx, int ny);

/// A cloth's particles at rest (before movePins()) and its triangles.
struct ClothGeometry {
    State state;                              ///< positions at rest, zero velocities, w = 1/m_i (0: pinned)
    std::vector<Eigen::Vector3i> triangles;   ///< the surface as particle index triples
};

/// The cloth of a scene at rest: the grid (makeGridState(), gridTriangles()) or, with spec.mesh, the
/// mesh's vertices at \f$ \vec x_i = \vec o + R\,(s\,\vec v_i) \f$ (o = origin, R = rotation,
/// s = scale) with lumped masses (lumpedMasses(): a third of each adjacent triangle's area, scaled to
/// the total mass) and its triangles. Pinned particles have w = 0.
/// @param spec  a validated cloth (a mesh cloth has meshData)
/// @return      particles and triangles
ClothGeometry makeClothGeometry(const ClothSpec& spec);

/// Moves the pinned particles of spec.moves to their positions (`"to"` in the scene), velocity zero.
/// Call it after the rest shape was taken (rest lengths, bending angles, measures).
/// @param s     the cloth's particles
/// @param spec  the cloth
void movePins(State& s, const ClothSpec& spec);

}  // namespace clothlab
