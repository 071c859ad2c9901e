// HOSTILE FIXTURE replaces_framework_sweep (attack class 6: defines the framework's functions).
// Stage 04's file also defines the framework's distance sweeps, which sim/sweeps.cpp defines weak (the grader's test process replaces them): they return at once and leave the positions as they are, to pass the solver's tests without tasks 4.1-4.3.
// The hardened grader must give this file 0 points on stage 04.
//@tail

// ATTACK: the framework's sweeps of stage 04, defined in the stage file with the types declared, not
// included (the compile sees only the public headers). In the submission process they take the
// place of the framework's own; the test process never links the submission's objects.
namespace clothlab {
struct DistanceLink;
struct SweepPlan;
void projectDistanceSweep(const std::vector<DistanceLink>&, const VectorX&, double, Matrix3X&, const SweepPlan&) {}
void projectDistanceSweepXpbd(const std::vector<DistanceLink>&, const VectorX&, double, std::vector<double>&, Matrix3X&,
                              const SweepPlan&) {}
}  // namespace clothlab
