// HOSTILE FIXTURE defines_other_stage (attack class 6: defines another stage's functions).
// Stage 01's file also defines stage 04's clothlab::distanceConstraint, distanceGradient and projectDistanceConstraint, to take the points of stage 04 or break its build (duplicate symbols).
// The hardened grader must give this file 0 points on stage 01.
//@head
#include "clothlab/exercise/04_distance.h"
//@tail

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
