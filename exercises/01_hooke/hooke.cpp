// Stage 01 — Hooke spring and time integration.
// Task sheet: exercises/01_hooke/README.md
// Contract (arguments, units, requirements): framework/include/clothlab/exercise/01_hooke.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 01
// Stuck? `./lab hint 1.1` (or 1.2, ...) asks a question and names the slide; add 2 for one sub-step, 3 for the formula.
#include "clothlab/exercise/01_hooke.h"
#include "clothlab/core/not_implemented.h"

namespace clothlab {

// ---- Task 1.1: Hooke's law --------------------------------------------------
Vec3 hookeForce(const Vec3& p0, const Vec3& p1, double k, double l0) {
    // TODO 1.1: Hooke's spring force on p1 (task sheet 1.1; contract in the header)
    (void)p0; (void)p1; (void)k; (void)l0;
    throw NotImplemented("exercise 1.1 hookeForce");
}

// ---- Task 1.2: damping along the spring -------------------------------------
Vec3 springDampingForce(const Vec3& p0, const Vec3& p1, const Vec3& v0, const Vec3& v1, double kd) {
    // TODO 1.2: damping along the spring (task sheet 1.2; contract in the header)
    (void)p0; (void)p1; (void)v0; (void)v1; (void)kd;
    throw NotImplemented("exercise 1.2 springDampingForce");
}

// ---- Task 1.3: explicit Euler -----------------------------------------------
void explicitEulerStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    // TODO 1.3: explicit Euler step (task sheet 1.3; contract in the header)
    (void)x; (void)v; (void)w; (void)force; (void)dt;
    throw NotImplemented("exercise 1.3 explicitEulerStep");
}

// ---- Task 1.4: symplectic Euler ---------------------------------------------
void symplecticEulerStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    // TODO 1.4: symplectic Euler step (task sheet 1.4; contract in the header)
    (void)x; (void)v; (void)w; (void)force; (void)dt;
    throw NotImplemented("exercise 1.4 symplecticEulerStep");
}

// ---- Task 1.5: velocity Verlet ----------------------------------------------
void velocityVerletStep(Matrix3X& x, Matrix3X& v, const VectorX& w, const ForceField& force, double dt) {
    // TODO 1.5: velocity Verlet step (task sheet 1.5; contract in the header)
    (void)x; (void)v; (void)w; (void)force; (void)dt;
    throw NotImplemented("exercise 1.5 velocityVerletStep");
}

}  // namespace clothlab
