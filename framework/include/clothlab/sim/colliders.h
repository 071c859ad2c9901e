/// @file colliders.h
/// @brief The geometry of the static colliders, shared by the solver's measures, the run checks and the app.
#pragma once
#include "clothlab/core/scene.h"
#include "clothlab/core/types.h"

namespace clothlab {

/// Signed distance d(x) from the collider's surface, m: positive outside, zero on it, negative inside.
/// Plane: \f$ d = (\vec x - \vec q)\cdot\vec n \f$ (q = collider.point, n = collider.normal);
/// sphere: \f$ d = |\vec x - \vec c| - R \f$ (c = collider.point, R = collider.radius).
/// A particle with thickness h keeps d ≥ h; its penetration is max(0, h − d).
/// @param c  the collider
/// @param x  a point, m
/// @return   d(x), m
double colliderDistance(const Collider& c, const Vec3& x);

}  // namespace clothlab
