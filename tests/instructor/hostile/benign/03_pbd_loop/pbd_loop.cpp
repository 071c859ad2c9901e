// Stage 03 — the PBD loop.
// Task sheet: exercises/03_pbd_loop/README.md
// Formulas and argument units: framework/include/clothlab/exercise/03_pbd_loop.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 03
//
// BENIGN FIXTURE: the stub with harmless student additions. It scores 0 (every task still
// throws NotImplemented) but a careful screen must ACCEPT it: nothing here is an attack.
#include <cmath>

#include <Eigen/Dense>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/03_pbd_loop.h"
#include <array>
#include <cstdio>
#include <numeric>


// Harmless student additions: std::array, a constexpr function, a helper in namespace clothlab.
namespace clothlab {
double meanOf(const std::array<double, 3>& a) { return std::accumulate(a.begin(), a.end(), 0.0) / 3.0; }
}  // namespace clothlab

namespace {
constexpr double square(double x) { return x * x; }
}  // namespace

namespace clothlab {

// ---- Task 3.1: dampVelocities ------------------------------------------------
void dampVelocities(const Matrix3X& x, Matrix3X& v, const VectorX& w, double kDamping) {
    // TODO 3.1: over the particles with w_i > 0 (m_i = 1/w_i) compute x_cm, v_cm, the angular
    //           momentum L = sum r_i x (m_i v_i) and the inertia I = sum m_i (|r_i|^2 Id - r_i r_i^T),
    //           omega = I^-1 L (pseudo-inverse when I is singular, e.g. Eigen::SelfAdjointEigenSolver),
    //           then v_i += kDamping (v_cm + omega x r_i - v_i). Pinned particles keep their velocity.
    (void)x; (void)v; (void)w; (void)kDamping;
    static_assert(square(2.0) == 4.0, "constexpr works");
    std::fprintf(stderr, "debug: mean %g\n", clothlab::meanOf({1.0, 2.0, 3.0}));
    throw NotImplemented("exercise 3.1 dampVelocities");
}

// ---- Task 3.2: stiffness per iteration ---------------------------------------
double iterationStiffness(double k, int iterations) {
    // TODO 3.2: k' = 1 - (1 - k)^(1/n); n = 0 returns k.
    (void)k; (void)iterations;
    static_assert(square(2.0) == 4.0, "constexpr works");
    std::fprintf(stderr, "debug: mean %g\n", clothlab::meanOf({1.0, 2.0, 3.0}));
    throw NotImplemented("exercise 3.2 iterationStiffness");
}

// ---- Task 3.3: one PBD step, lines (5)-(16) ----------------------------------
void pbdStep(PbdParticles& P, const PbdCallbacks& cb, double kDamping, int iterations, double dt) {
    // TODO 3.3: write lines (5)-(16) of the slides in this order, one or two lines each:
    //   (5)  f = 0 (3 x N), cb.externalForces(x, v, f) if set, v_i += dt w_i f_i
    //   (6)  dampVelocities(x, v, w, kDamping)
    //   (7)  p = x + dt v
    //   (8)  cb.generateCollisionConstraints(x, p) if set
    //   (9)-(11) `iterations` times: cb.projectConstraints(p) if set
    //   (13) v = (p - x) / dt   (14) x = p
    //   (16) cb.velocityUpdate(x, v) if set
    (void)P; (void)cb; (void)kDamping; (void)iterations; (void)dt;
    static_assert(square(2.0) == 4.0, "constexpr works");
    std::fprintf(stderr, "debug: mean %g\n", clothlab::meanOf({1.0, 2.0, 3.0}));
    throw NotImplemented("exercise 3.3 pbdStep");
}

}  // namespace clothlab
