/// @file 06_collision.h
/// @brief Stage 06 (Position Based Dynamics): collision constraints (Kollisions-Constraint) and velocityUpdate.
///
/// The student writes these functions in `exercises/06_collision/collision.cpp`;
/// the task sheet is `exercises/06_collision/README.md`. Notation as on the slides:
/// x_i position at the start of the step, p_i predicted position, q_s a point on the collider's
/// surface, n_s its outward unit normal there, h the thickness (solver.thickness).
/// The constraint is the inequality
/// \f[ C(\vec p) = (\vec p - \vec q_s)\cdot\vec n_s - h \ \ge\ 0 \f]
/// (the slides print "+ h"; with an outward normal the particle must stay h *outside*, hence − h).
#pragma once
#include <vector>

#include "clothlab/core/types.h"

namespace clothlab {

/// A plane collider for exercise 6.1: the points x with (x − point)·normal ≥ 0 are outside.
struct PlaneCollider {
    Vec3 point{0, 0, 0};       ///< a point on the plane, m
    Vec3 normal{0, 1, 0};      ///< outward unit normal
    double friction = 0.0;     ///< Coulomb friction coefficient μ ≥ 0
    double restitution = 0.0;  ///< coefficient of restitution e in [0, 1]
};

/// A sphere collider for exercise 6.2: the points x with |x − center| ≥ radius are outside.
struct SphereCollider {
    Vec3 center{0, 0, 0};      ///< centre, m
    double radius = 0.5;       ///< radius, m, > 0
    double friction = 0.0;     ///< Coulomb friction coefficient μ ≥ 0
    double restitution = 0.0;  ///< coefficient of restitution e in [0, 1]
};

/// One collision constraint, generated per step for particle i (line (8) of the algorithm).
struct CollisionConstraint {
    int i = 0;                ///< particle index
    Vec3 q{0, 0, 0};          ///< q_s: point on the collider surface, m
    Vec3 n{0, 1, 0};          ///< n_s: outward unit normal at q_s
    Vec3 start{0, 0, 0};      ///< x_i at the start of the step, m (for static friction)
    double vnBefore = 0.0;    ///< normal velocity before the solve, (p_i − x_i)·n_s / Δt, m/s (negative: approaching)
    double friction = 0.0;    ///< Coulomb friction coefficient μ of the collider
    double restitution = 0.0; ///< coefficient of restitution e of the collider
};

/// Exercise 6.1 — collision constraint against a plane (collider.point = a point on it,
/// collider.normal = outward unit normal). The plane bounds a half-space, so the path x → p
/// cannot pass it unnoticed: generate a constraint exactly when the predicted position violates it,
/// C(p) < 0, with q_s = collider.point and n_s = collider.normal (however far below the plane p is).
/// Fill every field of `out`: i, q, n, start = x, the collider's friction and restitution, and vnBefore,
/// the normal component (along n_s) of the velocity the prediction implies over the step, (p − x)/Δt
/// (negative while approaching).
/// @param i         particle index
/// @param x         position at the start of the step, m
/// @param p         predicted position, m
/// @param collider  a plane
/// @param h         thickness, m, h ≥ 0
/// @param dt        time step Δt > 0, s
/// @param out       the constraint (written only when one is generated)
/// @return          true if a constraint was generated
bool generatePlaneConstraint(int i, const Vec3& x, const Vec3& p, const PlaneCollider& collider, double h, double dt,
                             CollisionConstraint* out);

/// Exercise 6.2 — collision constraint against a sphere (centre c = collider.center, radius
/// R = collider.radius), generated along the path x → p so that a fast particle cannot tunnel
/// through. Work with the inflated sphere of radius R_h = R + h (the thickness included).
/// Requirements:
/// - x outside the inflated sphere: generate exactly when the straight path from x to p enters it
///   (also when p itself is outside again: no tunnelling); n_s is the outward unit normal of the sphere
///   at the point where the path *first* enters it (the entry point);
/// - x inside (|x − c| < R_h): generate only if p is inside too, with n_s pointing from c towards p
///   (p at the centre: the direction of x − c, or (0, 1, 0) if that is zero too);
/// - q_s is the point of the sphere's surface (radius R, not R_h) in the direction n_s from c, so that
///   C = (p − q_s)·n_s − h measures the distance to the inflated sphere along n_s;
/// - the other fields as in generatePlaneConstraint(); never NaN (also for a particle at rest).
/// @param i, x, p, h, dt, out  as in generatePlaneConstraint()
/// @param collider             a sphere
/// @return                     true if a constraint was generated
bool generateSphereConstraint(int i, const Vec3& x, const Vec3& p, const SphereCollider& collider, double h, double dt,
                              CollisionConstraint* out);

/// Exercise 6.3 — projection of a collision constraint, only when it is violated (C(p) < 0).
///
/// Requirements: a static collider has infinite mass, so the particle alone moves, the shortest way
/// out (along n_s) and the whole way: C(p + Δp) = 0 after one projection. Plus static friction at
/// position level: take the moved point p' = p + Δp and its tangential displacement over the step,
/// the part of p' − x perpendicular to n_s (x = c.start); if that is shorter than μ times the
/// penetration depth |C(p)|, the particle sticks: Δp also removes the tangential displacement.
/// Not violated (C ≥ 0: an inequality never pulls), or w = 0 (pinned): zero.
/// @param p  predicted position, m
/// @param w  inverse mass, 1/kg
/// @param h  thickness, m
/// @param c  the constraint
/// @return   Δp, m
Vec3 projectCollisionConstraint(const Vec3& p, double w, double h, const CollisionConstraint& c);

/// Exercise 6.4 — velocityUpdate (line (16)): for every constraint generated this step, split the
/// particle's velocity after the solve into its normal part v_n (along n_s) and its tangential part v_t.
/// Requirements:
/// - restitution (coefficient e): the new normal velocity is the larger of v_n and the incoming
///   normal velocity vnBefore reflected at the surface and scaled by e (a ball leaves a plane with e
///   times the speed it hit it with);
/// - Coulomb (kinetic) friction: the tangential speed shrinks by μ times the normal velocity change of
///   the solve (v_n − vnBefore, counted only when positive), keeps its direction, and stops at zero:
///   friction stops a particle but never reverses it; a block on an incline slides with g(sin θ − μ cos θ);
/// - the velocity is reassembled from the new normal and tangential parts.
/// @param v         velocities, 3 x N, m/s (changed in place)
/// @param contacts  the constraints generated this step
void velocityUpdate(Matrix3X& v, const std::vector<CollisionConstraint>& contacts);

}  // namespace clothlab
