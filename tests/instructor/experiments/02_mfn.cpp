// Stage 02's experiment, graded by the instructor (not in the student copy: no target leaves this file).
// Predict: Provot's estimate of the largest stable time step, pi sqrt(m/k), for one particle of the
// soft cloth (scenes/mfn_hanging.json) on one structural spring. Measure: the critical dt of symplectic
// Euler with `./lab study stability` on the student's own code. The measurement is graded against the
// same bisection run here with the student's code, which must reproduce theory: symplectic Euler is
// stable iff omega_max dt < 2, omega_max the fastest mode of the network (eigenvalues of M^-1 K).
#include <cmath>

#include <gtest/gtest.h>

#include "clothlab/exercise/02_mfn.h"
#include "clothlab/study/stability.h"
#include "clothlab/study/theory.h"
#include "experiment_scenes.h"
#include "test_util.h"

using namespace clothlab;

TEST(Experiments, CriticalTimeStepPredicted) {
    const Scene scene = parseScene(kScene_mfn_hanging, "scenes/mfn_hanging.json");
    const double m = scene.cloth.mass / (scene.cloth.nx * scene.cloth.ny), k = scene.springs.structural.k;
    const double provot = M_PI * std::sqrt(m / k);
    EXPECT_GRADED(testing_util::gradePrediction("02_mfn", "critical_dt", provot, 0.02 * provot,
                                              "Provot's estimate of the largest stable time step for one particle on one spring, s"));
}

TEST(Experiments, CriticalTimeStepMeasured) {
    const Scene scene = parseScene(kScene_mfn_hanging, "scenes/mfn_hanging.json");
    const double omega = maxAngularFrequency(scene), theory = theoreticalCriticalDt(Method::SymplecticEuler, omega);
    StabilityCriteria shortRuns;  // 300 steps per run, not the study's 1000: the grader calls the forces in another process
    shortRuns.steps = 300;
    const double own = measureCriticalDt(scene, Method::SymplecticEuler, theory / 3, theory * 3, shortRuns);
    const testing::AssertionResult physics =
        std::abs(own - theory) <= 0.1 * theory
            ? testing::AssertionSuccess()
            : testing::AssertionFailure() << "with your forces the cloth's stability limit is not 2 / omega_max of its network (the "
                                             "stage's Task2_* tests show where)";
    EXPECT_GRADED(testing_util::gradeMeasurement("02_mfn", "critical_dt", own, 0.1 * own, physics,
                                               "the measured critical time step of symplectic Euler, s"));
}
