// Graded tests of stage 03 — the PBD loop.
// Test names start with the task they check (Task3_3 = exercise 3.3). Points: 03_pbd_loop.points.json.
// The loop is tested with forces and constraints written here (no distance, bending or collision
// code of stages 04-06), so this stage is graded on its own. Task 3.3 calls your dampVelocities (3.1).
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "clothlab/exercise/03_pbd_loop.h"
#include "test_util.h"

using namespace clothlab;

namespace {

using testing_util::str;

const Vec3 kG(0.0, -9.81, 0.0);

// A small "cloth": a 3 x 3 grid of particles with different masses.
PbdParticles smallCloth() {
    PbdParticles P;
    P.x.resize(3, 9);
    P.w.resize(9);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            P.x.col(r * 3 + c) = Vec3(0.5 * c, -0.5 * r, 0.1 * c * r);
            P.w[r * 3 + c] = 1.0 + 0.5 * ((r + 2 * c) % 3);
        }
    P.v = Matrix3X::Zero(3, 9);
    P.p = P.x;
    return P;
}

Vec3 momentum(const PbdParticles& P) {
    Vec3 m = Vec3::Zero();
    for (int i = 0; i < P.x.cols(); ++i)
        if (P.w[i] > 0) m += P.v.col(i) / P.w[i];
    return m;
}
Vec3 angularMomentum(const PbdParticles& P) {
    Vec3 L = Vec3::Zero();
    for (int i = 0; i < P.x.cols(); ++i)
        if (P.w[i] > 0) L += P.x.col(i).cross(P.v.col(i) / P.w[i]);
    return L;
}

// Gravity as an external force: f_i = m_i g (none on pinned particles).
PbdCallbacks gravityOnly(const VectorX& w) {
    PbdCallbacks cb;
    cb.externalForces = [w](const Matrix3X&, const Matrix3X&, Matrix3X& f) {
        for (int i = 0; i < f.cols(); ++i)
            if (w[i] > 0) f.col(i) += kG / w[i];
    };
    return cb;
}

}  // namespace

// ---- Task 3.1 ------------------------------------------------------------------------------------
TEST(Task3_1_DampVelocities, RigidMotionIsNotDamped) {
    PbdParticles P = smallCloth();
    const Vec3 vlin(0.3, -1.0, 2.0), omega(0.5, 2.0, -1.0);
    for (int i = 0; i < 9; ++i) P.v.col(i) = vlin + omega.cross(P.x.col(i));
    const Matrix3X before = P.v;
    dampVelocities(P.x, P.v, P.w, 0.7);
    const double largestVelocityChange = (P.v - before).cwiseAbs().maxCoeff();
    EXPECT_LESS(largestVelocityChange, 1e-10)
        << "the largest change of a velocity component of a rigidly moving and spinning cloth (k = 0.7), in m/s: damping acts "
           "on motion relative to the rigid motion only, so a rigid translation plus rotation must not be slowed";
}

TEST(Task3_1_DampVelocities, KeepsMomentumAndAngularMomentumWhileRelativeMotionDecays) {
    PbdParticles P = smallCloth();
    const Vec3 omega(0.0, 3.0, 0.5);
    for (int i = 0; i < 9; ++i)
        P.v.col(i) = Vec3(1, 0, 0) + omega.cross(P.x.col(i)) + Vec3(std::sin(3.0 * i), std::cos(5.0 * i), 0.3 * i - 1);
    const Vec3 P0 = momentum(P), L0 = angularMomentum(P);
    auto relative = [&] {  // kinetic energy of the motion relative to the best rigid fit (least squares here)
        Eigen::MatrixXd A = Eigen::MatrixXd::Zero(27, 6);
        Eigen::VectorXd b(27);
        for (int i = 0; i < 9; ++i) {
            const double sm = std::sqrt(1.0 / P.w[i]);
            const Vec3 r = P.x.col(i);
            Eigen::Matrix3d rx;  // omega x r = -[r]x omega
            rx << 0, r.z(), -r.y(), -r.z(), 0, r.x(), r.y(), -r.x(), 0;
            A.block<3, 3>(3 * i, 0) = sm * Eigen::Matrix3d::Identity();
            A.block<3, 3>(3 * i, 3) = sm * rx;
            b.segment<3>(3 * i) = sm * P.v.col(i);
        }
        const Eigen::VectorXd sol = A.colPivHouseholderQr().solve(b);
        return 0.5 * (A * sol - b).squaredNorm();
    };
    const double rel0 = relative();
    ASSERT_GREATER(rel0, 0.1) << "test set-up (not your code): the kinetic energy of the motion relative to the best rigid fit, "
                                 "in J: the test's velocities must have a non-rigid part";
    dampVelocities(P.x, P.v, P.w, 0.5);
    const double momentumChange = (momentum(P) - P0).norm(), angularMomentumChange = (angularMomentum(P) - L0).norm();
    EXPECT_LESS(momentumChange, 1e-10) << "the total momentum of the cloth after dampVelocities (k = 0.5): damping removes only "
                                          "relative motion and must not change it; it went from " << str(P0) << " to "
                                       << str(momentum(P)) << " kg m/s";
    EXPECT_LESS(angularMomentumChange, 1e-10)
        << "the total angular momentum of the cloth after dampVelocities (k = 0.5): damping removes only relative motion, the "
           "rigid rotation must keep the cloth's angular momentum; it went from " << str(L0) << " to " << str(angularMomentum(P))
        << " kg m^2/s";
    const double relativeEnergy = relative();
    EXPECT_CLOSE(relativeEnergy, 0.25 * rel0, 1e-9 * rel0)
        << "the kinetic energy of the motion relative to the best rigid fit, in J, after dampVelocities with k = 0.5: it must "
           "halve the relative velocities, so quarter their energy from " << rel0 << " J";
}

TEST(Task3_1_DampVelocities, PinnedParticlesAndZeroCoefficient) {
    PbdParticles P = smallCloth();
    P.w[0] = 0.0;
    for (int i = 0; i < 9; ++i) P.v.col(i) = Vec3(i, -i, 0.5 * i);
    P.v.col(0).setZero();
    const Matrix3X before = P.v;
    dampVelocities(P.x, P.v, P.w, 0.0);
    const double largestVelocityChange = (P.v - before).cwiseAbs().maxCoeff();
    EXPECT_EXACT(largestVelocityChange, 0.0) << "the largest change of a velocity component by dampVelocities with k_damping = 0, "
                                                "in m/s: no damping must change no velocity";
    dampVelocities(P.x, P.v, P.w, 1.0);
    EXPECT_TRUE(P.v.allFinite()) << "the velocities after dampVelocities (k = 1) with a pinned particle (w = 0, infinite mass): "
                                    "they must be finite, not NaN; got " << str(P.v);
    EXPECT_EXACT(P.v.col(0).norm(), 0.0) << "the speed of the pinned particle 0 after dampVelocities (k = 1), in m/s: a pinned "
                                            "particle keeps its zero velocity; its velocity is " << str(P.v.col(0));
}

TEST(Task3_1_DampVelocities, ParticlesOnALineHaveNoSpinAboutIt) {
    PbdParticles P;
    P.x = Matrix3X::Zero(3, 3);
    P.x(0, 1) = 1.0, P.x(0, 2) = 2.0;  // on the x axis: I is singular
    P.w = VectorX::Ones(3);
    P.v = Matrix3X::Zero(3, 3);
    P.v(1, 0) = -1.0, P.v(1, 2) = 1.0;  // spin about z
    P.v(0, 1) = 0.4;                    // plus motion along the line
    dampVelocities(P.x, P.v, P.w, 1.0);
    EXPECT_TRUE(P.v.allFinite()) << "the velocities of three particles on a line after dampVelocities (k = 1): the inertia tensor "
                                    "is singular (no rotation about the line is defined), yet they must be finite; got " << str(P.v);
    EXPECT_CLOSE(P.v(1, 0), -1.0, 1e-9) << "the y velocity of particle 0, in m/s, of three particles on the x axis spinning about z: "
                                           "the spin is rigid motion and must survive damping with k = 1";
    EXPECT_CLOSE(P.v(0, 1), 0.4 / 3, 1e-9) << "the x velocity of the middle particle, in m/s: its motion along the line (0.4 m/s, "
                                              "a stretching) is relative motion, k = 1 must leave only the common drift 0.4/3";
}

// ---- Task 3.2 ------------------------------------------------------------------------------------
TEST(Task3_2_IterationStiffness, GivesTheSameTotalEffectForAnyIterationCount) {
    for (double k : {0.1, 0.5, 0.9})
        for (int n : {1, 2, 10, 100}) {
            const double kp = iterationStiffness(k, n);
            double left = 1.0;  // the fraction of an error C still there: each projection takes k' of it
            for (int i = 0; i < n; ++i) left -= kp * left;
            EXPECT_CLOSE(left, 1.0 - k, 1e-12)
                << "the fraction of an error C left after n = " << n << " projections with k' = iterationStiffness(" << k
                << ", " << n << ") = " << kp << ", each removing the fraction k' of what is left: n iterations together "
                << "must act like one projection with k = " << k << ", which leaves 1 - k";
        }
    EXPECT_SAME_DOUBLE(iterationStiffness(0.3, 1), 0.3) << "the per-iteration stiffness for k = 0.3 and 1 iteration: one "
                                                           "projection must do the whole job, so it must be k itself";
    EXPECT_SAME_DOUBLE(iterationStiffness(1.0, 7), 1.0) << "the per-iteration stiffness for k = 1 and 7 iterations: a fully stiff "
                                                           "constraint must stay fully stiff in every iteration";
    EXPECT_SAME_DOUBLE(iterationStiffness(0.0, 7), 0.0) << "the per-iteration stiffness for k = 0 and 7 iterations: a constraint "
                                                           "without stiffness must stay without it";
    EXPECT_SAME_DOUBLE(iterationStiffness(0.4, 0), 0.4) << "the per-iteration stiffness for k = 0.4 and 0 iterations: the header's "
                                                           "convention for no iterations is k itself";
}

// ---- Task 3.3 ------------------------------------------------------------------------------------
TEST(Task3_3_PbdStep, FreeFallFollowsTheParabola) {
    // Without constraints, PBD is symplectic Euler: each particle moves as that integrator moves it (the
    // recurrence below, stepped here), off the parabola x0 + v0 t + g t^2/2 by its first-order error.
    for (double dt : {0.01, 0.005}) {
        PbdParticles P = smallCloth();
        const Vec3 v0(1.0, 2.0, -0.5);
        for (int i = 0; i < 9; ++i) P.v.col(i) = v0;
        const Matrix3X x0 = P.x;
        const auto cb = gravityOnly(P.w);
        const int n = static_cast<int>(std::lround(1.0 / dt));
        for (int s = 0; s < n; ++s) pbdStep(P, cb, 0.0, 5, dt);
        const double t = n * dt;
        for (int i = 0; i < 9; ++i) {
            Vec3 xs = x0.col(i), vs = v0;  // symplectic Euler, stage 01: v += dt g, then x += dt v
            for (int s = 0; s < n; ++s) vs += dt * kG, xs += dt * vs;
            const Vec3 exact = x0.col(i) + v0 * t + 0.5 * kG * t * t;
            const double distanceFromSymplecticEuler = (P.x.col(i) - xs).norm();
            EXPECT_LESS(distanceFromSymplecticEuler, 1e-9 * (1 + xs.norm()))
                << "the distance of particle " << i << " at t = 1 s with dt = " << dt << " from where symplectic Euler puts it, in m: "
                << "without constraints PBD's lines (5), (7), (13), (14) must move it as that integrator does; x = " << str(P.x.col(i))
                << ", symplectic Euler " << str(xs) << " (the parabola of exact free fall: " << str(exact) << ")";
            const double velocityError = (P.v.col(i) - (v0 + kG * t)).norm();
            EXPECT_LESS(velocityError, 1e-9) << "the distance of particle " << i << "'s velocity from free fall's v0 + g t at t = 1 s "
                                                "with dt = " << dt << ", in m/s: it must be exact; got " << str(P.v.col(i))
                                             << ", free fall " << str(v0 + kG * t);
        }
    }
}

TEST(Task3_3_PbdStep, PinnedParticlesNeverMove) {
    PbdParticles P = smallCloth();
    P.w[0] = 0.0, P.w[2] = 0.0;  // two top corners
    const Matrix3X x0 = P.x;
    PbdCallbacks cb = gravityOnly(P.w);
    const VectorX w = P.w;
    cb.projectConstraints = [w](Matrix3X& p) {
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                if (c + 1 < 3) testing_util::projectRod(p, w, r * 3 + c, r * 3 + c + 1, 0.5);
                if (r + 1 < 3) testing_util::projectRod(p, w, r * 3 + c, (r + 1) * 3 + c, 0.5);
            }
    };
    for (int s = 0; s < 200; ++s) pbdStep(P, cb, 0.1, 10, 0.01);
    const double pinnedDisplacement = (P.x.col(0) - x0.col(0)).norm() + (P.x.col(2) - x0.col(2)).norm();
    EXPECT_EXACT(pinnedDisplacement, 0.0) << "how far the pinned corners 0 and 2 (w = 0) moved in 200 steps, in m: a pinned particle "
                                             "never moves; they are at " << str(P.x.col(0)) << " and " << str(P.x.col(2));
    EXPECT_EXACT(P.v.col(0).norm(), 0.0) << "the speed of the pinned corner 0 after 200 steps, in m/s: a pinned particle's velocity "
                                            "must stay zero; it is " << str(P.v.col(0));
    EXPECT_LESS(P.x(1, 7), x0(1, 7) - 0.01) << "the height y of the free bottom particle 7 after 200 steps, in m: gravity must pull "
                                               "it down by more than 1 cm";
}

TEST(Task3_3_PbdStep, ZeroIterationsGivePlainPrediction) {
    PbdParticles P = smallCloth();
    for (int i = 0; i < 9; ++i) P.v.col(i) = Vec3(0.1 * i, 0, 1);
    const Matrix3X x0 = P.x, v0 = P.v;
    PbdCallbacks cb = gravityOnly(P.w);
    cb.projectConstraints = [](Matrix3X& p) { p.setZero(); };  // would be obvious if called
    const double dt = 0.02;
    pbdStep(P, cb, 0.0, 0, dt);
    for (int i = 0; i < 9; ++i) {
        const Vec3 v1 = v0.col(i) + dt * kG;
        const Vec3 x1 = x0.col(i) + dt * v1;
        const double positionError = (P.x.col(i) - x1).norm(), velocityError = (P.v.col(i) - v1).norm();
        EXPECT_LESS(positionError, 1e-14) << "the position of particle " << i << " after a step with zero solver iterations: "
                                             "without projections it must be the unconstrained prediction " << str(x1)
                                          << "; got " << str(P.x.col(i));
        EXPECT_LESS(velocityError, 1e-12) << "the velocity of particle " << i << " after a step with zero solver iterations: "
                                             "without projections it must be the velocity of free flight under the forces, "
                                          << str(v1) << "; got " << str(P.v.col(i));
    }
}

TEST(Task3_3_PbdStep, LinesRunInTheSlidesOrder) {
    PbdParticles P = smallCloth();
    for (int i = 0; i < 9; ++i) P.v.col(i) = Vec3(1, 0, 0);
    const Matrix3X x0 = P.x;
    const double dt = 0.1;
    std::vector<std::string> log;
    PbdCallbacks cb;
    cb.externalForces = [&](const Matrix3X& x, const Matrix3X&, Matrix3X& f) {
        log.push_back("forces");
        EXPECT_EXACT((x - x0).norm(), 0.0) << "how far the positions passed to externalForces are from the start of the step, in m: "
                                              "line (5) evaluates the forces at the positions of the start of the step";
        f.col(4) = Vec3(0, 10, 0);
    };
    cb.generateCollisionConstraints = [&](const Matrix3X& x, const Matrix3X& p) {
        log.push_back("generate");
        EXPECT_EXACT((x - x0).norm(), 0.0) << "how far x passed to generateCollisionConstraints is from the start of the step, "
                                              "in m: at line (8) x must still hold the positions of the start of the step";
        const Vec3 v4 = Vec3(1, 0, 0) + dt * P.w[4] * Vec3(0, 10, 0);
        const Vec3 predicted4 = x0.col(4) + dt * v4;
        EXPECT_LESS((p.col(4) - predicted4).norm(), 1e-14)
            << "the prediction p of particle 4 passed to generateCollisionConstraints: at line (8) it must be the unconstrained "
               "prediction with the updated velocity, " << str(predicted4) << "; got " << str(p.col(4));
    };
    cb.projectConstraints = [&](Matrix3X& p) {
        log.push_back("project");
        p.col(3) += Vec3(0, 0, 0.01);  // each sweep moves particle 3 by 1 cm in z
    };
    cb.velocityUpdate = [&](const Matrix3X& x, Matrix3X& v) {
        log.push_back("velocityUpdate");
        EXPECT_CLOSE(x(2, 3), x0(2, 3) + 0.03, 1e-14) << "the z position of particle 3 passed to velocityUpdate, in m: after "
                                                         "3 sweeps of +1 cm each, line (14) must have accepted the projected p";
        EXPECT_CLOSE(v(2, 3), 0.03 / dt, 1e-12) << "the z velocity of particle 3 passed to velocityUpdate, in m/s: line (13) "
                                                   "must derive it from the 3 cm the projections moved it in dt = 0.1 s";
        v.col(3).setZero();
    };
    pbdStep(P, cb, 0.0, 3, dt);
    const std::vector<std::string> want = {"forces", "generate", "project", "project", "project", "velocityUpdate"};
    EXPECT_EQ(log, want) << "the order of the callbacks in one step with 3 iterations: the slides' algorithm runs them as (5), "
                            "(8), (10) once per iteration, (16)";
    EXPECT_EXACT(P.v.col(3).norm(), 0.0) << "the speed of particle 3 after the step, in m/s: velocityUpdate (line 16) set it to "
                                            "zero, and that must be the step's result; its velocity is " << str(P.v.col(3));
    EXPECT_CLOSE(P.x(2, 3), x0(2, 3) + 0.03, 1e-14) << "the z position of particle 3 after the step, in m: the step must end at "
                                                       "the projected positions (3 sweeps of +1 cm)";
}

TEST(Task3_3_PbdStep, DampsBeforePredicting) {
    // Two free particles flying apart; k_damping = 1 leaves only the rigid (common) motion.
    PbdParticles P;
    P.x = Matrix3X::Zero(3, 2);
    P.x(0, 1) = 1.0;
    P.w = VectorX::Ones(2);
    P.v = Matrix3X::Zero(3, 2);
    P.v(0, 0) = -1.0, P.v(0, 1) = 3.0;  // v_cm = (1, 0, 0)
    P.p = P.x;
    pbdStep(P, PbdCallbacks{}, 1.0, 4, 0.1);
    EXPECT_CLOSE(P.v(0, 0), 1.0, 1e-12) << "the x velocity of particle 0, in m/s, of two particles flying apart (-1 and 3 m/s) "
                                           "after a step with k_damping = 1: full damping must leave only the common motion 1 m/s";
    EXPECT_CLOSE(P.x(0, 0), 0.1, 1e-12) << "the x position of particle 0 after the step (dt = 0.1 s), in m: with k_damping = 1 "
                                           "it must move with the damped, common velocity 1 m/s";
    EXPECT_CLOSE(P.x(0, 1), 1.1, 1e-12) << "the x position of particle 1 after the step (dt = 0.1 s), in m: with k_damping = 1 "
                                           "it must move with the damped, common velocity 1 m/s";
}

TEST(Task3_3_PbdStep, DampingActsOnThisStepsForces) {
    // Two equal particles at rest on the x axis; a force pushes only particle 0 along the axis.
    // Line (5) gives particle 0 the velocity dt w f; line (6) with k_damping = 1 then leaves only the
    // rigid motion, which for two particles on a line pushed along it is the common velocity
    // (momentum conservation: v_cm = dt f / (2 m)). So both particles move by dt^2 f / (2 m).
    PbdParticles P;
    P.x = Matrix3X::Zero(3, 2);
    P.x(0, 1) = 1.0;
    P.w = VectorX::Ones(2);  // 1 kg each
    P.v = Matrix3X::Zero(3, 2);
    P.p = P.x;
    PbdCallbacks cb;
    cb.externalForces = [](const Matrix3X&, const Matrix3X&, Matrix3X& f) { f(0, 0) = 10.0; };
    const double dt = 0.1;
    pbdStep(P, cb, 1.0, 1, dt);
    const double common = dt * dt * 10.0 / 2.0;  // m
    EXPECT_CLOSE(P.x(0, 1), 1.0 + common, 1e-12)
        << "the x position of particle 1, in m, after one step in which a 10 N force pushed only particle 0 toward it "
           "(1 kg each, dt = 0.1 s, k_damping = 1): line (6) damps the velocities that line (5) has just changed, so full "
           "damping shares this step's push between both particles";
    EXPECT_CLOSE(P.x(0, 0), common, 1e-12) << "the x position of particle 0, in m, after the same step: full damping leaves "
                                              "only the common velocity of the two particles";
}

TEST(Task3_3_PbdStep, SwingingChainKeepsItsLinks) {
    // Two links from a pinned particle, released horizontally: a double pendulum whose links the
    // solver iterations keep at their rest lengths, and which never rises above its start.
    PbdParticles P;
    P.x = Matrix3X::Zero(3, 3);
    P.x(0, 1) = 0.5, P.x(0, 2) = 1.0;
    P.w = VectorX::Constant(3, 2.0);
    P.w[0] = 0.0;
    P.v = Matrix3X::Zero(3, 3);
    P.p = P.x;
    PbdCallbacks cb = gravityOnly(P.w);
    const VectorX w = P.w;
    cb.projectConstraints = [w](Matrix3X& p) {
        testing_util::projectRod(p, w, 0, 1, 0.5);
        testing_util::projectRod(p, w, 1, 2, 0.5);
    };
    double lowest = 0.0, highest = -1.0;
    for (int s = 0; s < 200; ++s) {
        pbdStep(P, cb, 0.0, 50, 0.005);
        lowest = std::min(lowest, P.x(1, 2));
        if (s > 100) highest = std::max(highest, P.x(1, 2));
        const double firstLink = (P.x.col(1) - P.x.col(0)).norm(), secondLink = (P.x.col(2) - P.x.col(1)).norm();
        EXPECT_CLOSE(firstLink, 0.5, 5e-3) << "the length of the first link of the swinging chain after step " << s
                                           << ", in m: 50 solver iterations must keep it at its rest length 0.5 m (5 mm)";
        EXPECT_CLOSE(secondLink, 0.5, 5e-3) << "the length of the second link of the swinging chain after step " << s
                                            << ", in m: 50 solver iterations must keep it at its rest length 0.5 m (5 mm)";
    }
    EXPECT_LESS(lowest, -0.9) << "the lowest height y of the chain's end over 1 s, in m: released horizontally it must swing down "
                                 "below -0.9 m";
    EXPECT_LESS(highest, 1e-3) << "the highest height y of the chain's end in its second half second, in m: without energy input "
                                  "it must never rise above its start height 0";
}

// ============================ Randomised property tests =======================================
// Random orientations, scales from 1 mm to 100 m, random masses (0.1 g to 100 g per particle) and
// uneven forces; seeds 1..kPropertySeeds (test_util.h). Expected behaviour from physics.

namespace {
using testing_util::forEachSeed;
using testing_util::RandomGeometry;

// Nine particles scattered in a box of size s (three dimensions, not a coordinate plane), random masses.
PbdParticles randomBody(RandomGeometry& G, double s, double mMin, double mMax) {
    PbdParticles P;
    P.x.resize(3, 9);
    P.w.resize(9);
    const Vec3 t = G.point(5.0 * s);
    for (int i = 0; i < 9; ++i) P.x.col(i) = G.point(s) + t, P.w[i] = 1.0 / G.logUniform(mMin, mMax);
    P.v = Matrix3X::Zero(3, 9);
    P.p = P.x;
    return P;
}

Vec3 centreOfMass(const PbdParticles& P) {
    Vec3 c = Vec3::Zero();
    double m = 0;
    for (int i = 0; i < P.x.cols(); ++i)
        if (P.w[i] > 0) c += P.x.col(i) / P.w[i], m += 1.0 / P.w[i];
    return c / m;
}
}  // namespace

TEST(Task3_1_DampVelocities, RigidMotionSurvivesAtAnyScaleAndMass) {
    // A body that moves and spins rigidly, v_i = V + omega x (x_i - x_cm), has no motion to damp, whatever its
    // size (1 mm to 100 m), its particle masses (0.1 g to 100 g) or the direction of its spin.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const double s = G.scale();
        PbdParticles P = randomBody(G, s, 1e-4, 1e-1);
        const Vec3 V = G.point(s), omega = G.uniform(0.1, 10.0) * G.unitVector(), xc = centreOfMass(P);
        for (int i = 0; i < 9; ++i) P.v.col(i) = V + omega.cross(Vec3(P.x.col(i) - xc));
        const Matrix3X before = P.v;
        const double k = G.uniform(0.2, 1.0);
        dampVelocities(P.x, P.v, P.w, k);
        const double vscale = V.norm() + omega.norm() * s;
        if (!P.v.allFinite() || (P.v - before).cwiseAbs().maxCoeff() > 1e-8 * vscale)
            return testing::AssertionFailure()
                   << "A rigidly moving and spinning body must not be slowed by dampVelocities, also when it is small or light: "
                      "size " << s << " m, particle masses from " << 1.0 / P.w.maxCoeff() << " kg to " << 1.0 / P.w.minCoeff()
                   << " kg, spin omega = " << str(omega) << " rad/s, k_damping = " << k << ": a velocity changed by "
                   << (P.v - before).cwiseAbs().maxCoeff() << " m/s. The moment of inertia of such a body is tiny (kg m^2 "
                      "scale with m s^2): an absolute threshold for 'zero inertia' loses its spin.";
        return testing::AssertionSuccess();
    });
}

TEST(Task3_1_DampVelocities, NearlyStraightClothKeepsItsSpinAndMomenta) {
    // Nine particles almost on a line (0.1 % to 1 % off it): the inertia tensor is nearly, but not exactly,
    // singular. The spin about the line is still rigid motion and must survive, and the damping of the
    // remaining motion keeps the momentum and the angular momentum.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const double s = G.logUniform(0.1, 100.0), off = G.logUniform(1e-3, 1e-2);
        const Eigen::Matrix3d R = G.rotation();
        const Vec3 axis = R.col(0);
        PbdParticles P;
        P.x.resize(3, 9), P.w.resize(9), P.v.resize(3, 9);
        for (int i = 0; i < 9; ++i) {
            P.x.col(i) = R * Vec3(s * G.uniform(-1, 1), off * s * G.uniform(-1, 1), off * s * G.uniform(-1, 1));
            P.w[i] = 1.0 / G.logUniform(0.05, 1.0);
        }
        const Vec3 xc = centreOfMass(P), V = G.point(s), omega = G.uniform(0.5, 5.0) * axis + G.point(1.0);
        for (int i = 0; i < 9; ++i) P.v.col(i) = V + omega.cross(Vec3(P.x.col(i) - xc));
        const Matrix3X rigid = P.v;
        dampVelocities(P.x, P.v, P.w, 1.0);
        const double vscale = V.norm() + omega.norm() * s;
        if (!P.v.allFinite() || (P.v - rigid).cwiseAbs().maxCoeff() > 1e-9 * vscale)
            return testing::AssertionFailure()
                   << "Particles nearly (but not exactly) on a line, " << off * 100 << " % of the length " << s
                   << " m off it, spinning rigidly with omega = " << str(omega) << " rad/s about their centre: this is rigid "
                      "motion and must survive k_damping = 1, including the spin about the line; a velocity changed by "
                   << (P.v - rigid).cwiseAbs().maxCoeff() << " m/s. Only an exactly singular inertia tensor may lose an axis.";
        for (int i = 0; i < 9; ++i) P.v.col(i) += G.point(s);  // plus relative motion
        Vec3 P0 = Vec3::Zero(), L0 = Vec3::Zero();
        for (int i = 0; i < 9; ++i) P0 += P.v.col(i) / P.w[i], L0 += Vec3(P.x.col(i) - xc).cross(Vec3(P.v.col(i))) / P.w[i];
        dampVelocities(P.x, P.v, P.w, G.uniform(0.2, 1.0));
        Vec3 P1 = Vec3::Zero(), L1 = Vec3::Zero();
        double pscale = 0;
        for (int i = 0; i < 9; ++i) {
            P1 += P.v.col(i) / P.w[i], L1 += Vec3(P.x.col(i) - xc).cross(Vec3(P.v.col(i))) / P.w[i];
            pscale += P.v.col(i).norm() / P.w[i];
        }
        if ((P1 - P0).norm() > 1e-9 * pscale || (L1 - L0).norm() > 1e-9 * pscale * s)
            return testing::AssertionFailure()
                   << "dampVelocities must keep the momentum and the angular momentum of a nearly straight body (" << off * 100
                   << " % off a line of length " << s << " m): momentum " << str(P0) << " -> " << str(P1)
                   << " kg m/s, angular momentum " << str(L0) << " -> " << str(L1) << " kg m^2/s.";
        return testing::AssertionSuccess();
    });
}

TEST(Task3_3_PbdStep, UnevenForcesRandomMassesAndOrientations) {
    // One PBD step with a different external force on every particle and a constraint written here (which
    // conserves momentum): the momentum of the free particles changes by exactly dt times the total force on them
    // (Newton's second law), pinned particles stay put whatever force acts on them, and rotating the whole
    // set-up rotates the result.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const double s = G.scale(), dt = G.logUniform(1e-4, 1e-2);
        PbdParticles P = randomBody(G, s, 1e-4, 1e-1);
        P.w[4] = 0.0;  // pinned
        for (int i = 0; i < 9; ++i) P.v.col(i) = G.point(s);
        P.v.col(4).setZero();
        Matrix3X fext(3, 9);
        for (int i = 0; i < 9; ++i) fext.col(i) = G.point(1e-3 * s / (dt * dt));  // uneven, also on the pinned one
        const Eigen::Matrix3d R = G.rotation();
        auto run = [&](const Eigen::Matrix3d& Q) {
            PbdParticles Pq = P;
            Pq.x = Q * P.x, Pq.v = Q * P.v, Pq.p = Pq.x;
            const VectorX w = P.w;
            const Matrix3X f = Q * fext;
            PbdCallbacks cb;
            cb.externalForces = [f](const Matrix3X&, const Matrix3X&, Matrix3X& out) { out += f; };
            cb.projectConstraints = [w](Matrix3X& p) { testing_util::pullTowardsCentreOfMass(p, w, 0.3); };
            pbdStep(Pq, cb, 0.0, 3, dt);
            return Pq;
        };
        const PbdParticles A = run(Eigen::Matrix3d::Identity()), B = run(R);
        Vec3 dP = Vec3::Zero(), F = Vec3::Zero();
        double pscale = 0;
        for (int i = 0; i < 9; ++i)
            if (P.w[i] > 0) {
                dP += (A.v.col(i) - P.v.col(i)) / P.w[i], F += fext.col(i);
                pscale += (A.v.col(i).norm() + P.v.col(i).norm()) / P.w[i];
            }
        if (!A.x.allFinite() || (dP - dt * F).norm() > 1e-9 * pscale)
            return testing::AssertionFailure()
                   << "Newton's second law: over one step the momentum of the free particles must change by dt times the total "
                      "external force on them, " << str(dt * F) << " N s, with a different force on every particle and masses "
                      "from " << 1.0 / P.w.maxCoeff() << " kg to " << 1.0 / P.w.minCoeff() << " kg; it changed by "
                   << str(dP) << " N s (dt = " << dt << " s).";
        if ((A.x.col(4) - P.x.col(4)).norm() != 0.0)
            return testing::AssertionFailure() << "A pinned particle (w = 0) must not move even when a force acts on it; it moved from "
                                               << str(P.x.col(4)) << " to " << str(A.x.col(4)) << ".";
        if ((B.x - R * A.x).cwiseAbs().maxCoeff() > 1e-9 * (s + P.x.cwiseAbs().maxCoeff()))
            return testing::AssertionFailure() << "Rotating the whole set-up (positions, velocities, forces) must rotate the result of "
                                                  "a PBD step: a particle ended " << (B.x - R * A.x).cwiseAbs().maxCoeff()
                                               << " m away from the rotated result.";
        return testing::AssertionSuccess();
    });
}

// ================================ Experiment (answers.json) ===================================
// The stage's experiment (task sheet, "Experiment"): predict from theory, measure with your own code,
// explain the difference, in exercises/03_pbd_loop/answers.json. This test checks only that the file is
// complete and well formed; the numbers are graded by the instructor.
TEST(Experiments, AnswerFileIsComplete) {
    EXPECT_TRUE(testing_util::answerFileIsComplete("03_pbd_loop", {"energy_drift_dt_0_01", "energy_drift_dt_0_005"}, {"energy_drift_dt_0_01", "energy_drift_dt_0_005"}));
}
