// Stage 01's experiment, graded by the instructor (not in the student copy: no target leaves this file).
// Predict: the convergence orders p (error ~ C dt^p) of symplectic Euler and velocity Verlet from theory.
// Measure: `./lab study precision scenes/spring.json` on the student's own code. The measurement is
// graded against the same study run here with the student's code, and earns points only when that run
// shows the theoretical order (a wrong integrator earns no measurement points).
#include <cmath>

#include <gtest/gtest.h>

#include "clothlab/exercise/01_hooke.h"
#include "clothlab/study/precision.h"
#include "experiment_scenes.h"
#include "test_util.h"

using namespace clothlab;

namespace {
// Local error O(dt^2) per step, 1/dt steps: order 1; Verlet is symmetric in time: order 2.
constexpr double kSymplecticEulerOrder = 1.0, kVerletOrder = 2.0, kOrderTolerance = 0.15;

// The fitted order of `method` on scenes/spring.json, as `./lab study precision scenes/spring.json` prints
// it: 7 time steps from scene dt / 10 to scene dt * 10, error at T = 1 s against the analytic solution.
double studiedOrder(Method method) {
    const Scene scene = parseScene(kScene_spring, "scenes/spring.json");
    PrecisionOptions o;
    o.methods = {method};
    o.dt_min = scene.solver.dt / 10, o.dt_max = scene.solver.dt * 10, o.dt_count = 7, o.end_time = 1.0;
    o.repeats = 1;  // the errors, not the run times, are graded
    return precisionStudy(scene, o).slopes.at(methodName(method));
}

testing::AssertionResult gradeOrderMeasured(const char* field, Method method, double theory) {
    const double own = studiedOrder(method);
    const testing::AssertionResult physics = std::abs(own - theory) <= kOrderTolerance
                                                 ? testing::AssertionSuccess()
                                                 : testing::AssertionFailure() << "the study of your " << methodName(method)
                                                                               << " fits an order that is not the method's (the stage's Task1_* tests show where)";
    return testing_util::gradeMeasurement("01_hooke", field, own, 0.02, physics, "the fitted order of " + std::string(methodName(method)));
}
}  // namespace

TEST(Experiments, SymplecticEulerOrderPredicted) {
    EXPECT_GRADED(testing_util::gradePrediction("01_hooke", "symplectic_euler_order", kSymplecticEulerOrder, kOrderTolerance,
                                              "the convergence order p of symplectic Euler"));
}

TEST(Experiments, VelocityVerletOrderPredicted) {
    EXPECT_GRADED(testing_util::gradePrediction("01_hooke", "velocity_verlet_order", kVerletOrder, kOrderTolerance,
                                              "the convergence order p of velocity Verlet"));
}

TEST(Experiments, SymplecticEulerOrderMeasured) {
    EXPECT_GRADED(gradeOrderMeasured("symplectic_euler_order", Method::SymplecticEuler, kSymplecticEulerOrder));
}

TEST(Experiments, VelocityVerletOrderMeasured) {
    EXPECT_GRADED(gradeOrderMeasured("velocity_verlet_order", Method::VelocityVerlet, kVerletOrder));
}
