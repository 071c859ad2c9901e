// Stage 01 — Hooke spring and time integration.
// Task sheet: exercises/01_hooke/README.md
// Formulas and argument units: framework/include/clothlab/exercise/01_hooke.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 01
//
// HOSTILE FIXTURE defines_other_stage (attack class 6: defines another stage's functions).
// Stage 01's file also defines stage 04's clothlab::distanceConstraint, distanceGradient and projectDistanceConstraint, to take the points of stage 04 or break its build (duplicate symbols).
// The hardened grader must give this file 0 points on stage 01.
#include "clothlab/exercise/01_hooke.h"
#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/04_distance.h"

namespace clothlab {

// ---- Task 1.1: Hooke's law --------------------------------------------------
Vec3 hookeForce(const Vec3& p0, const Vec3& p1, double k, double l0) {
    // TODO 1.1: F = -k (|p1 - p0| - l0) (p1 - p0) / |p1 - p0|, the force on p1.
    //           Return Vec3::Zero() when p0 and p1 coincide.
    (void)p0; (void)p1; (void)k; (void)l0;
    throw NotImplemented("exercise 1.1 hookeForce");
}

// ---- Task 1.2: damping along the spring -------------------------------------
Vec3 springDampingForce(const Vec3& p0, const Vec3& p1, const Vec3& v0, const Vec3& v1, double kd) {
    // TODO 1.2: F = -kd ((v1 - v0) . d) d with d the unit vector from p0 to p1.
    (void)p0; (void)p1; (void)v0; (void)v1; (void)kd;
    throw NotImplemented("exercise 1.2 springDampingForce");
}

// ---- Task 1.3: explicit Euler -----------------------------------------------
void explicitEulerStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    // TODO 1.3: evaluate the forces with force(x, v, f) (f is 3 x N),
    //           then x += dt * v_old and v += dt * w_i * f_i.
    (void)x; (void)v; (void)w; (void)force; (void)dt;
    throw NotImplemented("exercise 1.3 explicitEulerStep");
}

// ---- Task 1.4: symplectic Euler ---------------------------------------------
void symplecticEulerStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    // TODO 1.4: first the velocity, then the position with the NEW velocity.
    (void)x; (void)v; (void)w; (void)force; (void)dt;
    throw NotImplemented("exercise 1.4 symplecticEulerStep");
}

// ---- Task 1.5: velocity Verlet ----------------------------------------------
void velocityVerletStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    // TODO 1.5: half kick, drift, forces at the new positions, half kick.
    (void)x; (void)v; (void)w; (void)force; (void)dt;
    throw NotImplemented("exercise 1.5 velocityVerletStep");
}

}  // namespace clothlab

// ATTACK: stage 04's functions, defined in stage 01's file. When stage 04 is graded with the
// submission's stage 01 these replace (or collide with) the student's stage-04 code.
namespace clothlab {

double distanceConstraint(const Vec3& p1, const Vec3& p2, double d) {
    (void)p1; (void)p2; (void)d;
    return 0.0;  // "satisfied": whatever the stage-04 tests ask
}

Vec3 distanceGradient(const Vec3& p1, const Vec3& p2) {
    (void)p1; (void)p2;
    return Vec3::Zero();
}

DistanceCorrection projectDistanceConstraint(const Vec3& p1, const Vec3& p2, double w1, double w2, double d,
                                             double k) {
    (void)p1; (void)p2; (void)w1; (void)w2; (void)d; (void)k;
    return {Vec3::Zero(), Vec3::Zero()};
}

}  // namespace clothlab
