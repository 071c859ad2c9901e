/// @file scene_checks.h
/// @brief What a lecture picture shows, checked by numbers: cloth triangles through a collider, and a
/// cloth turned over (twisted) where it should hang flat. The tests of every shipped scene, the
/// renderer's summary (`./lab render`, the demo reel) and the app's status use them.
#pragma once
#include <string>
#include <vector>

#include <Eigen/Core>

#include "clothlab/core/scene.h"
#include "clothlab/core/types.h"

namespace clothlab {
class Simulation;
}

namespace clothlab {

/// Whether two triangles share a point: an edge of one crosses the other (segment–triangle test,
/// Möller–Trumbore). Exact for triangles that are not coplanar; coplanar ones count as apart.
/// @param a  the first triangle, 3 x 3 corners (columns), m
/// @param b  the second triangle, 3 x 3 corners, m
bool trianglesIntersect(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b);

/// The cloth triangles that pass through a collider's surface:
/// plane — a corner below it, \f$ (\vec x_k - \vec q)\cdot\vec n < 0 \f$;
/// sphere — the triangle's closest point to the centre c nearer than R, \f$ \min_{\vec y \in t} |\vec y - \vec c| < R \f$;
/// box, capsule, mesh — the triangle intersects one of colliderTriangles(c), the triangles the renderer draws.
/// The thickness h is not counted: a triangle within h of the surface but outside it passes.
/// @param x          particle positions, 3 x N, m
/// @param triangles  the cloth's triangles (indices into x)
/// @param c          the collider
/// @return           the indices of the triangles through it, ascending
std::vector<int> trianglesThroughCollider(const Matrix3X& x, const std::vector<Eigen::Vector3i>& triangles, const Collider& c);

/// The cloth's normals against a reference normal: how many triangles are turned over.
struct NormalFlips {
    int flipped = 0;     ///< triangles with \f$ \hat n_t \cdot \hat N < 0 \f$
    int triangles = 0;   ///< triangles with a normal (area above zero)
    double lowest = 1;   ///< \f$ \min_t \hat n_t \cdot \hat N \f$ (1 with no triangle)
};

/// The reference normal of a cloth: the area-weighted mean normal of its rest shape,
/// \f$ \hat N = \sum_t (\vec x_b - \vec x_a)\times(\vec x_c - \vec x_a) / |\cdot| \f$ (a flat cloth: its plane's normal;
/// the hammock: the plane of its hooks, where its slack strip hangs from).
/// @param rest       rest positions, 3 x N, m
/// @param triangles  the cloth's triangles
/// @return           \f$ \hat N \f$ (zero for a cloth without area)
Vec3 restNormal(const Matrix3X& rest, const std::vector<Eigen::Vector3i>& triangles);

/// Counts the triangles whose unit normal \f$ \hat n_t = (\vec x_b - \vec x_a)\times(\vec x_c - \vec x_a)/|\cdot| \f$
/// disagrees in sign with \f$ \hat N \f$. A hanging strip that twists by half a turn between its pins turns
/// half its triangles over; one that hangs flat turns none.
/// @param x          particle positions, 3 x N, m
/// @param triangles  the cloth's triangles
/// @param normal     the reference normal \f$ \hat N \f$ (restNormal())
NormalFlips normalFlips(const Matrix3X& x, const std::vector<Eigen::Vector3i>& triangles, const Vec3& normal);

/// Both checks on a running cloth, where they apply.
struct LookChecks {
    bool through_applies = false;  ///< a cloth with colliders
    int through = 0;               ///< its triangles through any collider (trianglesThroughCollider(), each counted once)
    int triangles = 0;             ///< the cloth's triangles
    bool flips_applies = false;    ///< a cloth hanging from pins, no collider, no wind: it should keep the side it shows
    NormalFlips flips;             ///< normalFlips() against restNormal() of the rest shape
};

/// The checks of the current state of `sim`: triangles through its colliders (a cloth with colliders),
/// triangles turned over (a cloth on pins, no colliders, no wind). Nothing applies to springs and chains.
/// @param sim  the simulation
LookChecks lookChecks(const Simulation& sim);

/// The checks that apply in one line, e.g. "0 of 1176 cloth triangles through a collider" or
/// "0 of 180 triangles turned over"; "" when none applies.
/// @param c  the checks (lookChecks())
std::string lookChecksLine(const LookChecks& c);

}  // namespace clothlab
