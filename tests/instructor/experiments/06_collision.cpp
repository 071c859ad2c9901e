// Stage 06's experiment, graded by the instructor (not in the student copy: no target leaves this file).
// Predict: the rebound height of the small cloth of scenes/pbd_bounce.json (dropped flat from H above the
// contact level, restitution e): it hits with sqrt(2 g H), leaves with e times that and rises to e^2 H.
// Measure: the height it rises to, with `./lab run scenes/pbd_bounce.json --every 1` on the student's own
// code. Graded against the same run made here with the student's code, which must reproduce e^2 H.
#include <cmath>

#include <gtest/gtest.h>

#include "clothlab/exercise/06_collision.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/sim/run.h"
#include "clothlab/sim/simulation.h"
#include "experiment_scenes.h"
#include "test_util.h"

using namespace clothlab;

namespace {
struct Bounce {
    double theory = 0, apex = -INFINITY;  // m
    bool bounced = false;
    std::string warning;  // the run's first warning (RunChecks), "" when none
};

// The drop of scenes/pbd_bounce.json with the code this binary links. theory = e^2 H, H the start height
// above the contact level y = h (every particle starts at the same height). With `run`: the highest mean
// height above the contact level after the first bounce (the mean height starts rising again), and the
// run's checks as `./lab run` makes them (a warning makes the measurement no result).
Bounce dropTheCloth(bool run) {
    const Scene scene = parseScene(kScene_pbd_bounce, "scenes/pbd_bounce.json");
    const double e = scene.colliders.at(0).restitution, h = scene.solver.thickness;
    auto sim = makeSimulation(scene);
    RunChecks checks(*sim);
    Bounce b;
    b.theory = e * e * (sim->state().x.row(1).mean() - h);
    double previous = sim->state().x.row(1).mean();
    for (long long n = 1; run && n <= scene.solver.steps; ++n) {
        const std::string unstable = checks.step(*sim, n);
        if (!unstable.empty()) throw std::runtime_error("your code's run of ./lab run scenes/pbd_bounce.json was " + unstable);
        const double y = sim->state().x.row(1).mean();
        if (!b.bounced && y > previous) b.bounced = true;
        if (b.bounced && y < previous) break;
        if (b.bounced) b.apex = y - h;
        previous = y;
    }
    if (run && !checks.warnings().empty()) b.warning = warningHeadline(checks.warnings().front(), scene);
    return b;
}
}  // namespace

TEST(Experiments, ReboundHeightPredicted) {
    const Bounce b = dropTheCloth(false);
    EXPECT_GRADED(testing_util::gradePrediction("06_collision", "rebound_height", b.theory, 0.01 * b.theory,
                                              "the rebound height above the contact level from e and H, m"));
}

TEST(Experiments, ReboundHeightMeasured) {
    const Bounce b = dropTheCloth(true);
    testing::AssertionResult physics =
        b.bounced && std::abs(b.apex - b.theory) <= 0.05 * b.theory
            ? testing::AssertionSuccess()
            : testing::AssertionFailure() << "with your collision code the cloth does not rebound as restitution demands (the stage's "
                                             "Task6_4 tests show where)";
    if (physics && !b.warning.empty())
        physics = testing::AssertionFailure() << "your code's run of ./lab run scenes/pbd_bounce.json warned (" << b.warning
                                              << "), so its numbers are no result; the warning names the pass and the exercise to fix";
    EXPECT_GRADED(testing_util::gradeMeasurement("06_collision", "rebound_height", b.apex, 0.02 * b.theory, physics,
                                               "the height the cloth rises to after the bounce, above the contact level, m"));
}
