// Stage 06 — collision constraints and velocityUpdate.
// Task sheet: exercises/06_collision/README.md
// Contract (arguments, units, requirements): framework/include/clothlab/exercise/06_collision.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 06
// Stuck? `./lab hint 6.1` (or 6.2, ...) asks a question and names the slide; add 2 for one sub-step, 3 for the formula.
#include <algorithm>
#include <cmath>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/06_collision.h"

namespace clothlab {

// ---- Task 6.1: plane -----------------------------------------------------------------
bool generatePlaneConstraint(int i, const Vec3& x, const Vec3& p, const PlaneCollider& collider, double h, double dt,
                             CollisionConstraint* out) {
    // TODO 6.1: collision constraint against a plane (task sheet 6.1; contract in the header)
    (void)i; (void)x; (void)p; (void)collider; (void)h; (void)dt; (void)out;
    throw NotImplemented("exercise 6.1 generatePlaneConstraint");
}

// ---- Task 6.2: sphere, along the path x -> p --------------------------------------------
bool generateSphereConstraint(int i, const Vec3& x, const Vec3& p, const SphereCollider& collider, double h, double dt,
                              CollisionConstraint* out) {
    // TODO 6.2: collision constraint against a sphere, along the path (task sheet 6.2; contract in the header)
    (void)i; (void)x; (void)p; (void)collider; (void)h; (void)dt; (void)out;
    throw NotImplemented("exercise 6.2 generateSphereConstraint");
}

// ---- Task 6.3: projection with static friction ----------------------------------------------
Vec3 projectCollisionConstraint(const Vec3& p, double w, double h, const CollisionConstraint& c) {
    // TODO 6.3: projection with static friction (task sheet 6.3; contract in the header)
    (void)p; (void)w; (void)h; (void)c;
    throw NotImplemented("exercise 6.3 projectCollisionConstraint");
}

// ---- Task 6.4: velocityUpdate -------------------------------------------------------------
void velocityUpdate(Matrix3X& v, const std::vector<CollisionConstraint>& contacts) {
    // TODO 6.4: velocityUpdate, restitution and kinetic friction (task sheet 6.4; contract in the header)
    (void)v; (void)contacts;
    throw NotImplemented("exercise 6.4 velocityUpdate");
}

}  // namespace clothlab
