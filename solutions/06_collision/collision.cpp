// Stage 06 — collision constraints and velocityUpdate (reference solution).
// Task sheet: exercises/06_collision/README.md
#include <algorithm>
#include <cmath>

#include "clothlab/exercise/06_collision.h"

namespace clothlab {

namespace {
// Fills a constraint of particle i with surface point q, normal n and the collider's μ and e.
void fill(int i, const Vec3& x, const Vec3& p, const Vec3& q, const Vec3& n, double friction, double restitution, double dt,
          CollisionConstraint* out) {
    out->i = i;
    out->q = q;
    out->n = n;
    out->start = x;
    out->vnBefore = (p - x).dot(n) / dt;
    out->friction = friction;
    out->restitution = restitution;
}
}  // namespace

// ---- Task 6.1: plane -----------------------------------------------------------------
bool generatePlaneConstraint(int i, const Vec3& x, const Vec3& p, const PlaneCollider& collider, double h, double dt,
                             CollisionConstraint* out) {
    if ((p - collider.point).dot(collider.normal) >= h) return false;
    fill(i, x, p, collider.point, collider.normal, collider.friction, collider.restitution, dt, out);
    return true;
}

// ---- Task 6.2: sphere, along the path x -> p --------------------------------------------
bool generateSphereConstraint(int i, const Vec3& x, const Vec3& p, const SphereCollider& collider, double h, double dt,
                              CollisionConstraint* out) {
    const Vec3& c = collider.center;
    const double R = collider.radius, Rh = R + h;
    Vec3 n;
    if ((x - c).norm() >= Rh) {
        // First t in [0, 1] with |x + t u - c| = Rh:  |u|^2 t^2 + 2 (u.f) t + |f|^2 - Rh^2 = 0.
        const Vec3 u = p - x, f = x - c;
        const double A = u.squaredNorm(), B = u.dot(f), Cq = f.squaredNorm() - Rh * Rh;
        if (A < 1e-300) return false;                 // not moving, and outside
        const double disc = B * B - A * Cq;
        if (disc < 0.0) return false;                 // the line misses the sphere
        const double t = (-B - std::sqrt(disc)) / A;  // entering root (Cq >= 0 so t >= 0 if B < 0)
        if (t < 0.0 || t > 1.0) return false;
        n = (f + t * u).normalized();
    } else {
        const Vec3 r = p - c;
        if (r.norm() >= Rh) return false;             // leaves the sphere during the step
        if (r.norm() > 1e-12) n = r.normalized();
        else if ((x - c).norm() > 1e-12) n = (x - c).normalized();
        else n = Vec3(0, 1, 0);
    }
    fill(i, x, p, c + R * n, n, collider.friction, collider.restitution, dt, out);
    return true;
}

// ---- Task 6.3: projection with static friction ----------------------------------------------
Vec3 projectCollisionConstraint(const Vec3& p, double w, double h, const CollisionConstraint& c) {
    const double C = (p - c.q).dot(c.n) - h;
    if (C >= 0.0 || w <= 0.0) return Vec3::Zero();  // inequality: only when violated
    Vec3 dp = -C * c.n;
    const Vec3 moved = p + dp - c.start;
    const Vec3 t = moved - moved.dot(c.n) * c.n;      // tangential displacement over the step
    if (t.norm() < c.friction * (-C)) dp -= t;        // static friction: stick
    return dp;
}

// ---- Task 6.4: velocityUpdate -------------------------------------------------------------
void velocityUpdate(Matrix3X& v, const std::vector<CollisionConstraint>& contacts) {
    for (const CollisionConstraint& c : contacts) {
        const Vec3 vi = v.col(c.i);
        const double vn = vi.dot(c.n);
        Vec3 vt = vi - vn * c.n;
        const double dvn = std::max(0.0, vn - c.vnBefore);       // normal velocity change of the solve
        const double vtLen = vt.norm();
        if (vtLen > 0.0) vt *= (vtLen - std::min(vtLen, c.friction * dvn)) / vtLen;  // Coulomb
        const double vnNew = std::max(vn, -c.restitution * c.vnBefore);              // restitution
        v.col(c.i) = vt + vnNew * c.n;
    }
}

}  // namespace clothlab
