/// @file colliders.h
/// @brief The geometry of the static colliders, shared by the solver, the measures, the run checks and the app;
/// the framework's collision constraints of the box, capsule and mesh colliders.
///
/// Planes and spheres are the students' exercises 6.1 and 6.2 (exercises/06_collision); the other
/// colliders produce the same CollisionConstraint here, C = (p − q_s)·n_s − h, which exercise 6.3
/// projects and exercise 6.4 turns into friction and restitution.
#pragma once
#include <vector>

#include <Eigen/Core>

#include "clothlab/core/mesh.h"
#include "clothlab/core/scene.h"
#include "clothlab/core/types.h"
#include "clothlab/exercise/06_collision.h"

namespace clothlab {

/// The point of a collider's surface closest to a point x, and the outward normal there.
struct SurfacePoint {
    Vec3 q{0, 0, 0};   ///< closest surface point q_s, m
    Vec3 n{0, 1, 0};   ///< outward unit normal n_s: (x − q)/|x − q| outside, −(x − q)/|x − q| inside, the surface's normal on it
    double d = 0.0;    ///< signed distance d(x), m: positive outside, negative inside
};

/// A static triangle mesh with a bounding-volume hierarchy (axis-aligned boxes, median split, up to 4
/// triangles per leaf), so that a closest-point query costs O(log T) for T triangles.
/// The sign of the distance comes from the angle-weighted pseudonormal of the closest feature (face,
/// edge or vertex; Bærentzen & Aanæs 2005): exact for a closed, consistently oriented mesh; for an open
/// mesh "outside" is the side its face normals point to.
class MeshShape {
public:
    /// @param mesh  a checked mesh (meshProblem() == ""), counter-clockwise seen from outside
    explicit MeshShape(TriangleMesh mesh);
    /// Closest surface point, outward normal and signed distance of x (see SurfacePoint).
    SurfacePoint closest(const Vec3& x) const;
    /// The same as closest(x), bit for bit, found faster when `near` is close to x: `near` is any point
    /// of the surface (e.g. the closest point of a point nearby), so the closest point is at most
    /// |x − near| away, and the search skips every box farther than that.
    /// @param x     the point, m
    /// @param near  a point of the mesh's surface, m
    SurfacePoint closest(const Vec3& x, const Vec3& near) const;
    /// The mesh, as placed in the scene.
    const TriangleMesh& mesh() const { return mesh_; }

private:
    struct Node {
        Eigen::Vector3d lo, hi;   // bounding box, m
        int left = -1, right = -1;  // children (inner node) or -1
        int first = 0, count = 0;   // leaf: triangles order_[first, first + count)
    };
    int build(int first, int count);
    /// closest(x) among the triangles closer than sqrt(bound2); false (s untouched) if none is.
    bool search(const Vec3& x, double bound2, SurfacePoint* s) const;
    TriangleMesh mesh_;
    Matrix3X faceNormal_;         // 3 x T
    Matrix3X edgeNormal_;         // 3 x 3T: pseudonormal of edge (f[k], f[k+1]) of triangle t at column 3t + k
    Matrix3X vertexNormal_;       // 3 x V: angle-weighted pseudonormals
    std::vector<int> order_;      // triangle indices, grouped by leaf
    std::vector<Node> nodes_;     // nodes_[0] is the root
    Matrix3X boxLo_, boxHi_;      // 3 x T: bounding box of triangle order_[k] at column k
};

/// Closest point of triangle abc to x (Ericson, Real-Time Collision Detection, 5.1.5: the Voronoi
/// regions of vertices, edges and face).
/// @param x        the point, m
/// @param a, b, c  the triangle's corners, m
/// @param feature  receives which feature is closest: 0..2 vertex a, b, c; 3 + k edge k (0: ab, 1: bc, 2: ca); 6 the face
/// @return         the closest point q of the triangle, \f$ |\vec x - \vec q| \f$ minimal
Vec3 closestOnTriangle(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c, int* feature);

/// The scene's plane collider as exercise 6.1 takes it (point, normal, μ, e).
/// @param c  a collider of type Plane
/// @return   its PlaneCollider
inline PlaneCollider planeCollider(const Collider& c) { return {c.point, c.normal, c.friction, c.restitution}; }

/// The scene's sphere collider as exercise 6.2 takes it (centre = c.point, radius, μ, e).
/// @param c  a collider of type Sphere
/// @return   its SphereCollider
inline SphereCollider sphereCollider(const Collider& c) { return {c.point, c.radius, c.friction, c.restitution}; }

/// Closest surface point, outward normal and signed distance of x from the collider:
/// plane: \f$ d = (\vec x - \vec q)\cdot\vec n \f$; sphere: \f$ d = |\vec x - \vec c| - R \f$;
/// box (centre c, axes R, half extents e, y = Rᵀ(x − c), u = |y| − e componentwise):
/// \f$ d = |\max(u, 0)| \f$ outside, \f$ d = \max_k u_k \f$ inside;
/// capsule (axis a–b, radius R): \f$ d = |\vec x - \vec s| - R \f$, s the closest point of the segment;
/// mesh: MeshShape::closest().
/// @param c  the collider
/// @param x  a point, m
/// @return   q_s, n_s and d(x)
SurfacePoint colliderSurface(const Collider& c, const Vec3& x);
/// colliderSurface(c, x), bit for bit, given a point `near` of the surface (for a mesh, the search
/// starts with the bound |x − near|: MeshShape::closest(x, near)).
/// @param c     the collider
/// @param x     a point, m
/// @param near  a point of c's surface, e.g. the closest point of a point near x, m
/// @return      q_s, n_s and d(x)
SurfacePoint colliderSurface(const Collider& c, const Vec3& x, const Vec3& near);

/// Signed distance d(x) from the collider's surface, m: positive outside, zero on it, negative inside
/// (colliderSurface(c, x).d). A particle with thickness h keeps d ≥ h; its penetration is max(0, h − d).
/// @param c  the collider
/// @param x  a point, m
/// @return   d(x), m
double colliderDistance(const Collider& c, const Vec3& x);

/// The collision constraint of a box, capsule or mesh collider along the path x → p (line (8) of the
/// algorithm), the same rules as exercise 6.2 for any collider inflated by h:
/// - x at least h outside: generated when the straight path x → p comes within h of the surface,
///   found by sphere tracing (t ← t + (d(x + t(p − x)) − h)/|p − x|, exact for a distance function),
///   so a fast particle cannot tunnel; n_s and q_s from the closest surface point of the entry point;
/// - x closer than h: generated only if p is closer than h too, with q_s and n_s of p;
/// - start = x, vnBefore = (p − x)·n_s/Δt, friction and restitution from the collider.
/// @param i, x, p, h, dt, out  as in generatePlaneConstraint() (exercise 6.1)
/// @param collider             a box, capsule or mesh
/// @param near                 optional (speed only, the result is the same): in, a point of the
///                             collider's surface near x, e.g. the last closest point of this particle
///                             (bounds a mesh's search, see colliderSurface()); out, the closest surface
///                             point of the last point looked at; null or NaN: none
/// @return                     true if a constraint was generated
bool generateSolidConstraint(int i, const Vec3& x, const Vec3& p, const Collider& collider, double h, double dt,
                             CollisionConstraint* out, Vec3* near = nullptr);

/// The collider's surface as flat triangles for drawing: box 12, capsule a cylinder with two
/// hemispheres of `segments` sides, mesh its own triangles; nothing for planes and spheres (drawn apart).
/// @param c         the collider
/// @param segments  sides around a round collider (≥ 3)
/// @return          3 x 3K corners, m: triangle k is columns 3k, 3k+1, 3k+2, counter-clockwise from outside
Matrix3X colliderTriangles(const Collider& c, int segments = 24);

}  // namespace clothlab
