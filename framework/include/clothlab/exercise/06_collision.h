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

#include "clothlab/core/scene.h"
#include "clothlab/core/types.h"

namespace clothlab {

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
/// cannot pass it unnoticed: generate a constraint when the predicted position is closer than h,
/// \f$ (\vec p - \vec q_s)\cdot\vec n_s < h \f$, with q_s = collider.point and n_s = collider.normal.
/// Fill every field of `out` (start = x, vnBefore = (p − x)·n_s/Δt, friction and restitution of the
/// collider).
/// @param i         particle index
/// @param x         position at the start of the step, m
/// @param p         predicted position, m
/// @param collider  a plane
/// @param h         thickness, m, h ≥ 0
/// @param dt        time step Δt > 0, s
/// @param out       the constraint (written only when one is generated)
/// @return          true if a constraint was generated
bool generatePlaneConstraint(int i, const Vec3& x, const Vec3& p, const Collider& collider, double h, double dt,
                             CollisionConstraint* out);

/// Exercise 6.2 — collision constraint against a sphere (centre c = collider.point, radius
/// R = collider.radius), generated along the path x → p so that a fast particle cannot tunnel
/// through. With the inflated radius R_h = R + h:
/// - x outside (|x − c| ≥ R_h): find the first t in [0, 1] with |x + t (p − x) − c| = R_h; if there
///   is one, the entry point is e = x + t (p − x), \f$\vec n_s = (\vec e - \vec c)/|\vec e - \vec c|\f$;
/// - x inside (|x − c| < R_h): generate only if |p − c| < R_h, with \f$\vec n_s = (\vec p - \vec c)/|\vec p - \vec c|\f$
///   (p at the centre: use the direction of x − c, or (0, 1, 0) if that is zero too);
/// - then \f$\vec q_s = \vec c + R\,\vec n_s\f$, and the other fields as in generatePlaneConstraint().
/// @param i, x, p, h, dt, out  as in generatePlaneConstraint()
/// @param collider             a sphere
/// @return                     true if a constraint was generated
bool generateSphereConstraint(int i, const Vec3& x, const Vec3& p, const Collider& collider, double h, double dt,
                              CollisionConstraint* out);

/// Exercise 6.3 — projection of a collision constraint, only when it is violated (C(p) < 0):
/// \f[ \Delta\vec p = -C(\vec p)\,\vec n_s \f]
/// (a static collider has infinite mass, so the particle moves the whole way), plus static friction
/// at position level: with the moved point p' = p + Δp and its tangential displacement over the step
/// \f$\vec t = (\vec p' - \vec x) - ((\vec p' - \vec x)\cdot\vec n_s)\,\vec n_s\f$ (x = c.start):
/// if \f$|\vec t| < \mu\,|C(\vec p)|\f$ the particle sticks, \f$\Delta\vec p \leftarrow \Delta\vec p - \vec t\f$.
/// Not violated, or w = 0 (pinned): zero.
/// @param p  predicted position, m
/// @param w  inverse mass, 1/kg
/// @param h  thickness, m
/// @param c  the constraint
/// @return   Δp, m
Vec3 projectCollisionConstraint(const Vec3& p, double w, double h, const CollisionConstraint& c);

/// Exercise 6.4 — velocityUpdate (line (16)): for every constraint generated this step, with
/// v_n = v_i·n_s the normal velocity after the solve:
/// - restitution: \f$ v_n' = \max(v_n,\ -e\,v_{n,before}) \f$;
/// - Coulomb (kinetic) friction: the tangential velocity \f$\vec v_t = \vec v_i - v_n\vec n_s\f$ loses
///   \f$\min(|\vec v_t|,\ \mu\,\Delta v_n)\f$ of its length, with the normal velocity change of the
///   solve \f$\Delta v_n = \max(0,\ v_n - v_{n,before})\f$;
/// - \f$ \vec v_i \leftarrow \vec v_t' + v_n'\,\vec n_s \f$.
/// @param v         velocities, 3 x N, m/s (changed in place)
/// @param contacts  the constraints generated this step
void velocityUpdate(Matrix3X& v, const std::vector<CollisionConstraint>& contacts);

}  // namespace clothlab
