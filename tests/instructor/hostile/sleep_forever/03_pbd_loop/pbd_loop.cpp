// Stage 03 — the PBD loop.
// Task sheet: exercises/03_pbd_loop/README.md
// Formulas and argument units: framework/include/clothlab/exercise/03_pbd_loop.h
//
// Replace each `throw NotImplemented(...)` by your code, then run
//     ./lab grade --stage 03
//
// HOSTILE FIXTURE sleep_forever (attack class 8: resource exhaustion).
// The tested function ignores SIGTERM and sleeps in a loop: it uses no CPU time, so a CPU-time limit alone never stops it, only a wall-clock limit.
// The hardened grader must give this file 0 points on stage 03.
#include <cmath>

#include <Eigen/Dense>

#include "clothlab/core/not_implemented.h"
#include "clothlab/exercise/03_pbd_loop.h"
#include <csignal>
#include <unistd.h>

// WARNING: never run this fixture outside the grader's sandbox (it is built to hurt the machine).

namespace {
void hostileSleep() {
    std::signal(SIGTERM, SIG_IGN);
    std::signal(SIGINT, SIG_IGN);
    for (;;) sleep(3600);  // no CPU time at all
}
}  // namespace

namespace clothlab {

// ---- Task 3.1: dampVelocities ------------------------------------------------
void dampVelocities(const Matrix3X& x, Matrix3X& v, const VectorX& w, double kDamping) {
    // TODO 3.1: over the particles with w_i > 0 (m_i = 1/w_i) compute x_cm, v_cm, the angular
    //           momentum L = sum r_i x (m_i v_i) and the inertia I = sum m_i (|r_i|^2 Id - r_i r_i^T),
    //           omega = I^-1 L (pseudo-inverse when I is singular, e.g. Eigen::SelfAdjointEigenSolver),
    //           then v_i += kDamping (v_cm + omega x r_i - v_i). Pinned particles keep their velocity.
    (void)x; (void)v; (void)w; (void)kDamping;
    hostileSleep();
    throw NotImplemented("exercise 3.1 dampVelocities");
}

// ---- Task 3.2: stiffness per iteration ---------------------------------------
double iterationStiffness(double k, int iterations) {
    // TODO 3.2: k' = 1 - (1 - k)^(1/n); n = 0 returns k.
    (void)k; (void)iterations;
    hostileSleep();
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
    hostileSleep();
    throw NotImplemented("exercise 3.3 pbdStep");
}

}  // namespace clothlab
