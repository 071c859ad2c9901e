// Stage 06 — collision constraints and velocityUpdate.
// Task sheet: exercises/06_collision/README.md
// Formulas and argument units: framework/include/clothlab/exercise/06_collision.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 06
//
// BENIGN FIXTURE: the stub with harmless student additions. It scores 0 (every task still
// throws NotImplemented) but a careful screen must ACCEPT it: nothing here is an attack.
#include <algorithm>
#include <cmath>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/06_collision.h"
#include <array>
#include <cstdio>
#include <vector>


// Harmless student additions: a constexpr table, a helper, printf, std::clamp.
namespace {
constexpr std::array<double, 3> kWeights{0.25, 0.5, 0.25};
double clamp01(double x) { return std::clamp(x, 0.0, 1.0); }
}  // namespace

double sumOfWeights() {
    double s = 0.0;
    for (double w : kWeights) s += w;
    return s;
}

namespace clothlab {

// ---- Task 6.1: plane -----------------------------------------------------------------
bool generatePlaneConstraint(int i, const Vec3& x, const Vec3& p, const PlaneCollider& collider, double h, double dt,
                             CollisionConstraint* out) {
    // TODO 6.1: if (p - q_s).n_s < h, fill *out (i, q = collider.point, n = collider.normal, start = x,
    //           vnBefore = (p - x).n / dt, friction, restitution) and return true; else return false.
    (void)i; (void)x; (void)p; (void)collider; (void)h; (void)dt; (void)out;
    std::printf("debug: weights %g, clamp %g\n", sumOfWeights(), clamp01(1.5));
    throw NotImplemented("exercise 6.1 generatePlaneConstraint");
}

// ---- Task 6.2: sphere, along the path x -> p --------------------------------------------
bool generateSphereConstraint(int i, const Vec3& x, const Vec3& p, const SphereCollider& collider, double h, double dt,
                              CollisionConstraint* out) {
    // TODO 6.2: with Rh = R + h: x outside -> first intersection of the segment x -> p with the sphere
    //           of radius Rh (a quadratic in t); x inside -> only if p is inside, normal from the centre
    //           to p. Then q = c + R n and the other fields as in 6.1.
    (void)i; (void)x; (void)p; (void)collider; (void)h; (void)dt; (void)out;
    std::printf("debug: weights %g, clamp %g\n", sumOfWeights(), clamp01(1.5));
    throw NotImplemented("exercise 6.2 generateSphereConstraint");
}

// ---- Task 6.3: projection with static friction ----------------------------------------------
Vec3 projectCollisionConstraint(const Vec3& p, double w, double h, const CollisionConstraint& c) {
    // TODO 6.3: C = (p - q).n - h; if C >= 0 or w == 0 return zero; dp = -C n; then static friction:
    //           t = tangential part of (p + dp - c.start); if |t| < mu |C|, dp -= t.
    (void)p; (void)w; (void)h; (void)c;
    std::printf("debug: weights %g, clamp %g\n", sumOfWeights(), clamp01(1.5));
    throw NotImplemented("exercise 6.3 projectCollisionConstraint");
}

// ---- Task 6.4: velocityUpdate -------------------------------------------------------------
void velocityUpdate(Matrix3X& v, const std::vector<CollisionConstraint>& contacts) {
    // TODO 6.4: for every contact: v_n = v.n, v_t = v - v_n n, dvn = max(0, v_n - vnBefore);
    //           shorten v_t by min(|v_t|, mu dvn); v_n' = max(v_n, -e vnBefore); v = v_t + v_n' n.
    (void)v; (void)contacts;
    std::printf("debug: weights %g, clamp %g\n", sumOfWeights(), clamp01(1.5));
    throw NotImplemented("exercise 6.4 velocityUpdate");
}

}  // namespace clothlab
