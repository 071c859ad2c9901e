/// @file mesh.h
/// @brief Triangle meshes from Wavefront OBJ files: a cloth made of any triangles, a static mesh collider.
///
/// Files are read with Debian's tinyobjloader (polygons are split into triangle fans) and then checked:
/// every problem is an InputError naming the scene file, the scene field and the OBJ file.
#pragma once
#include <string>
#include <vector>

#include <Eigen/Core>

#include "clothlab/core/types.h"

namespace clothlab {

/// A triangle mesh: vertex positions and index triples (counter-clockwise seen from the outside).
struct TriangleMesh {
    Matrix3X vertices;                       ///< 3 x V positions, m
    std::vector<Eigen::Vector3i> triangles;  ///< T triangles, indices into `vertices`
};

/// The first problem of a mesh, or "" for a good one. Checked, in this order: at least one face;
/// every index in [0, V); every triangle has an area above 1e-12 times its longest edge squared
/// (no zero-area triangle, no repeated vertex); every edge belongs to at most two triangles (manifold);
/// with `everyVertexUsed`, every vertex belongs to a triangle (a cloth particle must have a mass).
/// @param m                the mesh
/// @param everyVertexUsed  require every vertex to be in a face
/// @return                 e.g. "face 3 (vertices 0, 1, 1) has zero area", or ""
std::string meshProblem(const TriangleMesh& m, bool everyVertexUsed);

/// Reads a Wavefront OBJ file (all its objects and groups; only `v` and `f` matter) and checks it with meshProblem().
/// @param path             the OBJ file
/// @param sceneFile        the scene file naming it (for the error message)
/// @param field            the scene field naming it, e.g. "cloth.mesh"
/// @param everyVertexUsed  as in meshProblem()
/// @throws InputError      `<sceneFile>: <field>: <path>: <reason>` (missing or unreadable file, no faces,
///                         index out of range, degenerate triangle, non-manifold edge, unused vertex)
TriangleMesh loadObjMesh(const std::string& path, const std::string& sceneFile, const std::string& field,
                         bool everyVertexUsed);

/// Lumped particle masses of a cloth mesh: each triangle gives a third of its area to each of its
/// vertices, scaled so that the masses add up to the total:
/// \f$ m_i = m_{gesamt}\,\frac{\sum_{t \ni i} A_t / 3}{\sum_t A_t} \f$.
/// @param m      the mesh (no zero-area triangles, every vertex in a face)
/// @param total  total mass m_gesamt, kg
/// @return       m_i for every vertex, kg
VectorX lumpedMasses(const TriangleMesh& m, double total);

/// Unit normal of every triangle, \f$ \hat n_t = (x_b - x_a)\times(x_c - x_a) / |\cdot| \f$.
/// @param m  the mesh (no zero-area triangles)
/// @return   3 x T normals
Matrix3X triangleNormals(const TriangleMesh& m);

}  // namespace clothlab
