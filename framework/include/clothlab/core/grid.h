/// @file grid.h
/// @brief The regular particle grid every cloth is made of (Massepartikel auf einem Gitter).
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
/// @param spec  grid size (nx, ny ≥ 2), extent (m), total mass (kg), origin, orientation, pins
/// @return      state with nx*ny particles
State makeGridState(const ClothSpec& spec);

/// Two triangles per grid cell, counter-clockwise seen from +z (vertical) or +y (horizontal),
/// split along the diagonal from (c, r) to (c+1, r+1).
/// @param nx, ny  grid size
/// @return        2 (nx-1)(ny-1) triangles as particle index triples
std::vector<Eigen::Vector3i> gridTriangles(int nx, int ny);

}  // namespace clothlab
