/// @file topology.h
/// @brief Mesh topology helpers: the unique edges of a triangle mesh.
#pragma once
#include <vector>

#include <Eigen/Core>

namespace clothlab {

/// The unique edges of a triangle mesh, each once as (smaller index, larger index), sorted.
/// On a cloth grid (gridTriangles) these are the structural edges (Strukturfedern) and one
/// diagonal per cell (Scherfeder).
/// @param triangles  triangles as particle index triples
/// @return           edges as index pairs
std::vector<Eigen::Vector2i> uniqueEdges(const std::vector<Eigen::Vector3i>& triangles);

/// For every interior edge (shared by exactly two triangles) the two vertices opposite it, once each,
/// sorted: the ends of a bending spring across the edge (on a grid: particles one diagonal or, across a
/// cell's split, two apart). Works on any triangle mesh.
/// @param triangles  triangles as particle index triples
/// @return           pairs (smaller index, larger index)
std::vector<Eigen::Vector2i> oppositeVertices(const std::vector<Eigen::Vector3i>& triangles);

}  // namespace clothlab

namespace clothlab {

/// An order of constraints in which consecutive constraints rarely share a particle: a greedy graph
/// colouring (no two constraints of one colour share a particle), colours one after the other.
/// Gauss-Seidel over this order is as valid as over any other, and the processor can overlap
/// independent projections instead of waiting for each result (several times faster on a cloth).
/// @param particles   for each constraint the indices of its particles (entries < 0 are ignored)
/// @param nParticles  number of particles N (indices are in [0, N))
/// @return            a permutation of 0..M-1 (M = number of constraints)
std::vector<int> colourOrder(const std::vector<Eigen::Vector4i>& particles, int nParticles);

}  // namespace clothlab
