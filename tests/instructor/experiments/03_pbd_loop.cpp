// Stage 03's experiment, graded by the instructor (not in the student copy: no target leaves this file).
// Predict: the per-iteration stiffness k' that makes 10 iterations act like k = 0.9 (task 3.2's
// derivation). Measure: the curtain's max_strain after 3 s with 5 and with 50 iterations
// (`./lab run scenes/pbd_curtain.json ... --quiet`) on the student's own PBD loop. The measurements
// are graded against the same runs made here with the student's code, and earn points only when that
// code passes a first-principles check: a particle hanging from a pin on one distance constraint
// settles at the stretch (1 - k) g dt^2 / k, whatever the iteration count (the point of k').
#include <cmath>

#include <gtest/gtest.h>

#include "clothlab/exercise/03_pbd_loop.h"
#include "experiment_scenes.h"
#include "test_util.h"

using namespace clothlab;

namespace {
double curtainStrain(int iterations) {
    return testing_util::finalMetric(kScene_pbd_curtain, "scenes/pbd_curtain.json", {"solver.iterations=" + std::to_string(iterations)},
                                     "max_strain");
}

// The fixed point of one PBD step: the prediction stretches the constraint by s + g dt^2, the n
// projections with k' leave (1 - k') ^ n = 1 - k of it, and at rest that is s again.
testing::AssertionResult hangingParticleSettlesAtTheTheory() {
    const double k = 0.9, g = 9.81, dt = 0.01, d = 1.0;
    const int n = 10;
    PbdParticles P;
    P.x = Matrix3X::Zero(3, 2);
    P.x(1, 1) = -d;
    P.v = Matrix3X::Zero(3, 2);
    P.w = VectorX(2);
    P.w << 0.0, 1.0;
    P.p = P.x;
    const double kPrime = iterationStiffness(k, n);
    PbdCallbacks cb;
    cb.externalForces = [&](const Matrix3X&, const Matrix3X&, Matrix3X& f) { f.setZero(), f(1, 1) = -g; };  // m = 1 kg
    cb.projectConstraints = [&](Matrix3X& p) {
        const Vec3 e = p.col(1) - p.col(0);
        const double length = e.norm();
        if (length > 1e-12) p.col(1) -= kPrime * (length - d) * e / length;
    };
    for (int step = 0; step < 2000; ++step) pbdStep(P, cb, 0.0, n, dt);
    const double stretch = (P.x.col(1) - P.x.col(0)).norm() - d, theory = (1 - k) * g * dt * dt / k;
    if (P.x.allFinite() && std::abs(stretch - theory) <= 0.02 * theory) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "a particle hanging from a pin on one distance constraint (k = 0.9, 10 iterations) does not "
                                          "settle where PBD theory puts it with your loop and k' (the stage's Task3_* tests show where)";
}
}  // namespace

TEST(Experiments, IterationStiffnessPredicted) {
    EXPECT_GRADED(testing_util::gradePrediction("03_pbd_loop", "iteration_stiffness", 1.0 - std::pow(1.0 - 0.9, 1.0 / 10), 1e-3,
                                              "k' for k = 0.9 and 10 iterations, 1"));
}

TEST(Experiments, CurtainStrainMeasured) {
    const double own5 = curtainStrain(5), own50 = curtainStrain(50);
    testing::AssertionResult physics = hangingParticleSettlesAtTheTheory();
    if (physics && !(own50 < own5))
        physics = testing::AssertionFailure() << "with your loop 50 iterations do not make the curtain stiffer than 5";
    EXPECT_GRADED(testing_util::gradeMeasurement("03_pbd_loop", "max_strain_5_iterations", own5, 0.03 * own5, physics,
                                               "max_strain of pbd_curtain after 3 s with 5 iterations, 1"));
    EXPECT_GRADED(testing_util::gradeMeasurement("03_pbd_loop", "max_strain_50_iterations", own50, 0.03 * own50, physics,
                                               "max_strain of pbd_curtain after 3 s with 50 iterations, 1"));
}
