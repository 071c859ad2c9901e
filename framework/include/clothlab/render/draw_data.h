/// @file draw_data.h
/// @brief What the renderer draws: a plain copy of positions, topology and colliders (no GL here).
///
/// The renderer never sees a Simulation; it draws a DrawData filled from one (or from a scene's
/// initial state, or from a grid built in a test). Filling it needs no OpenGL.
#pragma once
#include <string>
#include <vector>

#include <Eigen/Core>

#include "clothlab/core/scene.h"
#include "clothlab/core/state.h"

namespace clothlab {

class Simulation;

/// Kind of an edge drawn in the spring/constraint overlay (colour by type).
enum class EdgeKind {
    Single,      ///< a lone spring or a chain link (stage 01)
    Structural,  ///< Strukturfeder / distance constraint between grid neighbours
    Shear,       ///< Scherfeder / distance constraint between diagonal neighbours
    Bending      ///< Biegefeder: neighbours two apart
};

/// Display name of an edge kind ("structural", ...).
/// @param kind  the kind
const char* edgeKindName(EdgeKind kind);

/// Everything one frame shows, in world coordinates (metres).
struct DrawData {
    Matrix3X x;                              ///< particle positions x_i, 3 x N, m
    VectorX w;                               ///< inverse masses w_i, N (w_i = 0: pinned, drawn as a red marker)
    std::vector<Eigen::Vector2i> edges;      ///< springs or distance constraints, particle index pairs
    std::vector<EdgeKind> edge_kind;         ///< kind of each edge (same length as edges)
    std::vector<double> rest_length;         ///< rest length l0 of each edge, m (for the strain colouring)
    std::vector<Eigen::Vector3i> triangles;  ///< cloth surface, counter-clockwise index triples (may be empty)
    Eigen::Matrix2Xd uv;                     ///< texture coordinates per particle in [0, 1]² (cloth only; else empty)
    std::vector<Collider> colliders;         ///< the scene's colliders
    /// Boxes, capsules and meshes as flat triangles (colliderTriangles()), one 3 x 3K matrix per collider, m
    std::vector<Matrix3X> collider_triangles;
    std::vector<Vec3> ghosts;                ///< where an analytic solution puts the particles (drawn translucent), m
    double t = 0.0;                          ///< simulated time, s (shown in the corner)
    std::string title;                       ///< one line shown in the corner (scene and method)
    std::string note;                        ///< one line shown at the bottom-left ("" = none), e.g. lookChecksLine()

    /// Strain of edge e: \f$ \varepsilon_e = |x_i - x_j| / l_0 - 1 \f$ (0 when l0 = 0).
    /// @param e  edge index
    double strain(int e) const;
};

/// Fills a DrawData from a running simulation: its state, edges(), triangles() and the scene's colliders.
/// Edge kinds and rest lengths are derived from the scene (cloth grid offsets; chain and spring l0).
/// For the single spring with a 1-D analytic solution, the ghost is the exact position
/// \f$ x_{anchor} + \xi(t)\, u \f$ (u: unit vector from the anchor to the start).
/// @param sim  the simulation
DrawData makeDrawData(const Simulation& sim);

/// The same for a scene's initial state without a simulation (e.g. when its method is not available):
/// the grid of a cloth (all structural, shear and bending neighbour pairs), the chain or the spring.
/// @param scene  the scene
DrawData makeDrawData(const Scene& scene);

/// A cloth grid's DrawData from a state: triangles from gridTriangles(), structural + shear + bending
/// edges, uv from the grid coordinates, rest lengths from `rest`.
/// @param spec   grid description (nx, ny, extent)
/// @param state  current particles (nx*ny)
/// @param rest   particles at rest (for l0), nx*ny
DrawData makeClothDrawData(const ClothSpec& spec, const State& state, const State& rest);

}  // namespace clothlab
