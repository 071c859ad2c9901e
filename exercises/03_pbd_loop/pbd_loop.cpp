// Stage 03 — the PBD loop.
// Task sheet: exercises/03_pbd_loop/README.md
// Contract (arguments, units, requirements): framework/include/clothlab/exercise/03_pbd_loop.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 03
// Stuck? `./lab hint 3.1` (or 3.2, ...) asks a question and names the slide; add 2 for one sub-step, 3 for the formula.
#include <cmath>

#include <Eigen/Dense>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/03_pbd_loop.h"

namespace clothlab {

// ---- Task 3.1: dampVelocities ------------------------------------------------
void dampVelocities(const Matrix3X& x, Matrix3X& v, const VectorX& w, double kDamping) {
    // TODO 3.1: dampVelocities, damping that spares rigid motion (task sheet 3.1; contract in the header)
    (void)x; (void)v; (void)w; (void)kDamping;
    throw NotImplemented("exercise 3.1 dampVelocities");
}

// ---- Task 3.2: stiffness per iteration ---------------------------------------
double iterationStiffness(double k, int iterations) {
    // TODO 3.2: stiffness per solver iteration (task sheet 3.2; contract in the header)
    (void)k; (void)iterations;
    throw NotImplemented("exercise 3.2 iterationStiffness");
}

// ---- Task 3.3: one PBD step, lines (5)-(16) ----------------------------------
void pbdStep(PbdParticles& P, const PbdCallbacks& cb, double kDamping, int iterations, double dt) {
    // TODO 3.3: one PBD step, slide lines (5) to (16) (task sheet 3.3; contract in the header)
    (void)P; (void)cb; (void)kDamping; (void)iterations; (void)dt;
    throw NotImplemented("exercise 3.3 pbdStep");
}

}  // namespace clothlab
