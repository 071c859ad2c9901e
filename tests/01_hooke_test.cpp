// Graded tests of stage 01 — Hooke spring and time integration.
// Test names start with the task they check (Task1_1 = exercise 1.1). Points: 01_hooke.points.json.
// Integrator tests use a force field written here (not your hookeForce), so every task is graded on its own.
#include <cmath>

#include <gtest/gtest.h>

#include "clothlab/exercise/01_hooke.h"
#include "clothlab/sim/rk4.h"
#include "test_util.h"

using namespace clothlab;

namespace {

constexpr double kPi = 3.14159265358979323846;

using testing_util::str;

// ---- A harmonic oscillator with a known solution, for the integrator tests ----------------
// One particle of mass m pulled towards the origin by F = -k x (no springs, no gravity).
struct Oscillator {
    double m = 1.0, k = 100.0;            // ω = 10 rad/s, T = 0.628 s
    Vec3 x0{1.0, 0.0, 0.0}, v0{0.0, 2.0, 0.0};
    double omega() const { return std::sqrt(k / m); }
    Vec3 exact(double t) const { return x0 * std::cos(omega() * t) + v0 / omega() * std::sin(omega() * t); }
    ForceField field() const {
        return [k = k](const Matrix3X& x, const Matrix3X&, Matrix3X& f) { f = -k * x; };
    }
    double energy(const Matrix3X& x, const Matrix3X& v) const {
        return 0.5 * m * v.col(0).squaredNorm() + 0.5 * k * x.col(0).squaredNorm();
    }
};

using Stepper = void (*)(Matrix3X&, Matrix3X&, const VectorX&, const ForceField&, double);

// Integrates the oscillator to time T; returns the largest position error along the way.
double maxError(Stepper step, double dt, double T) {
    Oscillator o;
    Matrix3X x = o.x0, v = o.v0;
    VectorX w = VectorX::Constant(1, 1.0 / o.m);
    const int n = static_cast<int>(std::lround(T / dt));
    double err = 0.0;
    for (int i = 1; i <= n; ++i) {
        step(x, v, w, o.field(), dt);
        err = std::max(err, (x.col(0) - o.exact(i * dt)).norm());
    }
    return err;
}

// Measured order p from the errors at dt and dt/2: p = log2(e(dt) / e(dt/2)), averaged over two halvings.
double measuredOrder(Stepper step) {
    const double e1 = maxError(step, 2e-3, 1.0), e2 = maxError(step, 1e-3, 1.0), e3 = maxError(step, 5e-4, 1.0);
    return 0.5 * (std::log2(e1 / e2) + std::log2(e2 / e3));
}

// Period (from upward zero crossings of x) and amplitude over a few periods of a 1-D oscillation.
void periodAndAmplitude(Stepper step, double dt, double* period, double* amplitude) {
    Oscillator o;
    o.v0.setZero();
    Matrix3X x = o.x0, v = o.v0;
    VectorX w = VectorX::Constant(1, 1.0 / o.m);
    std::vector<double> crossings;
    double amp = 0.0, t = 0.0;
    const int n = static_cast<int>(std::lround(3.0 * 2.0 * kPi / o.omega() / dt));
    for (int i = 0; i < n; ++i) {
        const double before = x(0, 0);
        step(x, v, w, o.field(), dt);
        t += dt;
        amp = std::max(amp, std::abs(x(0, 0)));
        if (before < 0.0 && x(0, 0) >= 0.0) crossings.push_back(t - dt * x(0, 0) / (x(0, 0) - before));
    }
    *period = crossings.size() >= 2 ? (crossings.back() - crossings.front()) / double(crossings.size() - 1) : 0.0;
    *amplitude = amp;
}

// Relative energy change max |E - E0| / E0 over `periods` periods, and the final E / E0.
void energyBehaviour(Stepper step, double dt, double periods, double* max_rel_change, double* final_ratio) {
    Oscillator o;
    Matrix3X x = o.x0, v = o.v0;
    VectorX w = VectorX::Constant(1, 1.0 / o.m);
    const double e0 = o.energy(x, v);
    const int n = static_cast<int>(std::lround(periods * 2.0 * kPi / o.omega() / dt));
    double worst = 0.0;
    for (int i = 0; i < n; ++i) {
        step(x, v, w, o.field(), dt);
        worst = std::max(worst, std::abs(o.energy(x, v) - e0) / e0);
    }
    *max_rel_change = worst;
    *final_ratio = o.energy(x, v) / e0;
}

// One step of each integrator on two particles, one of them pinned, with F(x, v) = -3 x - 0.5 v + (0, -1, 0).
struct OneStep {
    Matrix3X x{3, 2}, v{3, 2};
    VectorX w{2};
    ForceField field = [](const Matrix3X& x, const Matrix3X& v, Matrix3X& f) {
        f = -3.0 * x - 0.5 * v;
        f.row(1).array() -= 1.0;
    };
    Vec3 force(const Vec3& xi, const Vec3& vi) const { return -3.0 * xi - 0.5 * vi - Vec3(0, 1, 0); }
    OneStep() {
        x << 0.3, 0.0, -0.2, 1.0, 0.5, 0.0;
        v << 1.0, 0.0, 0.5, 0.0, -2.0, 0.0;
        w << 0.5, 0.0;  // particle 1 pinned
    }
};

// Ten steps; the pinned particle (w = 0) must not move.
testing::AssertionResult pinnedStaysPut(Stepper step) {
    OneStep s;
    const Vec3 x0 = s.x.col(1);
    for (int i = 0; i < 10; ++i) step(s.x, s.v, s.w, s.field, 0.1);
    if (s.x.col(1).isApprox(x0, 1e-12) && s.x.col(1).allFinite()) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "a particle with w = 0 must not move; it went from " << str(x0) << " to "
                                       << str(s.x.col(1));
}

}  // namespace

// ================================ Task 1.1: Hooke's law =====================================

TEST(Task1_1_HookeForce, PullsBackWhenStretched) {
    const Vec3 f = hookeForce(Vec3(0, 0, 0), Vec3(2, 0, 0), 10.0, 1.0);
    EXPECT_TRUE(f.isApprox(Vec3(-10, 0, 0), 1e-12))
        << "the force on p1 for p0 = (0, 0, 0), p1 = (2, 0, 0), k = 10, l0 = 1: the spring is stretched by 1, so it must pull p1 "
           "back towards p0 with k * 1 = 10 N, i.e. (-10, 0, 0); got " << str(f) << ".";
}

TEST(Task1_1_HookeForce, PushesApartWhenCompressed) {
    const Vec3 f = hookeForce(Vec3(0, 0, 0), Vec3(0, 0.5, 0), 10.0, 1.0);
    EXPECT_TRUE(f.isApprox(Vec3(0, 5, 0), 1e-12))
        << "the force on p1 for p0 = (0, 0, 0), p1 = (0, 0.5, 0), k = 10, l0 = 1: the spring is compressed by 0.5, so it must push "
           "p1 away from p0 with k * 0.5 = 5 N, i.e. (0, 5, 0) (a spring acts on the change of its length); got " << str(f) << ".";
}

TEST(Task1_1_HookeForce, MagnitudeIsStiffnessTimesStretch) {
    const Vec3 p0(1, 2, 3), dir = Vec3(2, -1, 2) / 3.0;  // unit vector
    const Vec3 f = hookeForce(p0, p0 + 3.0 * dir, 7.0, 1.0);
    EXPECT_CLOSE(f.norm(), 7.0 * 2.0, 1e-9)
        << "|p1 - p0| = 3, l0 = 1, k = 7: |F| must be k * 2 = 14, got " << f.norm()
        << " (the magnitude of the force on p1: stiffness times stretch, whatever the spring's length).";
    EXPECT_TRUE(f.normalized().isApprox(-dir, 1e-9))
        << "the direction of the force on p1: a stretched spring must pull p1 straight back towards p0, along " << str(-dir)
        << "; got the force " << str(f) << " (direction " << str(f.normalized()) << ").";
}

TEST(Task1_1_HookeForce, ZeroAtRestLength) {
    const Vec3 f = hookeForce(Vec3(1, 1, 1), Vec3(1, 1, 1) + Vec3(0.6, 0, 0.8), 50.0, 1.0);
    EXPECT_LESS(f.norm(), 1e-12) << "the force on p1 of a spring at its rest length (|p1 - p0| = l0 = 1) must vanish; got " << str(f);
}

TEST(Task1_1_HookeForce, NewtonsThirdLaw) {
    const Vec3 a(0.1, -0.4, 2.0), b(1.5, 0.3, -0.7);
    const Vec3 fb = hookeForce(a, b, 12.0, 0.8), fa = hookeForce(b, a, 12.0, 0.8);
    EXPECT_TRUE((fa + fb).norm() < 1e-12 && fb.norm() > 1.0)
        << "the forces on the two ends of a stretched spring (Newton's third law, actio = reactio): swapping the end points "
           "must give the opposite, non-zero force; F(a,b) = " << str(fb)
        << ", F(b,a) = " << str(fa);
}

TEST(Task1_1_HookeForce, IsMinusGradientOfSpringEnergy) {
    // E(p1) = k/2 (|p1 - p0| - l0)^2, so F = -dE/dp1. Central differences, h = 1e-6.
    const Vec3 p0(0.2, 0.1, -0.3), p1(1.1, -0.7, 0.4);
    const double k = 40.0, l0 = 0.5, h = 1e-6;
    auto energy = [&](const Vec3& p) { const double s = (p - p0).norm() - l0; return 0.5 * k * s * s; };
    Vec3 grad;
    for (int d = 0; d < 3; ++d) {
        Vec3 e = Vec3::Zero();
        e[d] = h;
        grad[d] = (energy(p1 + e) - energy(p1 - e)) / (2 * h);
    }
    const Vec3 f = hookeForce(p0, p1, k, l0);
    EXPECT_TRUE(f.isApprox(-grad, 1e-6)) << "the force on p1 must be minus the gradient of the spring energy E = k/2 (|p1-p0| - l0)^2 "
                                            "(relative 1e-6); finite differences give " << str(-grad) << ", your force is " << str(f);
}

TEST(Task1_1_HookeForce, CoincidentPointsGiveZeroNotNaN) {
    const Vec3 f = hookeForce(Vec3(1, 2, 3), Vec3(1, 2, 3), 100.0, 1.0);
    EXPECT_TRUE(f.allFinite()) << "the force on p1 for coincident points p0 == p1 must be a finite vector (the header's "
                                  "convention for an undefined direction), not NaN; got " << str(f);
    EXPECT_LESS(f.norm(), 1e-12) << "the force on p1 for coincident points p0 == p1: the direction is undefined, so the header "
                                    "requires the zero vector; got " << str(f);
}

// ============================ Task 1.2: damping along the spring ============================

TEST(Task1_2_SpringDamping, OpposesRelativeVelocityAlongSpring) {
    const Vec3 f = springDampingForce(Vec3(0, 0, 0), Vec3(0, 0, 2), Vec3(0, 0, 0), Vec3(0, 0, 3), 0.5);
    EXPECT_TRUE(f.isApprox(Vec3(0, 0, -1.5), 1e-12))
        << "the damping force on p1: p1 moves away from p0 with 3 m/s along the spring, kd = 0.5, so it must oppose that "
           "motion with kd * 3 = 1.5 N, i.e. (0, 0, -1.5); got "
        << str(f);
}

TEST(Task1_2_SpringDamping, UsesRelativeVelocityOnly) {
    const Vec3 v(0.3, -2.0, 1.0);
    const Vec3 f = springDampingForce(Vec3(0, 0, 0), Vec3(1, 1, 0), v, v, 4.0);
    EXPECT_LESS(f.norm(), 1e-12) << "the damping force on p1 when both ends move with the same velocity " << str(v)
                                 << ": a damper only resists relative motion, so it must vanish; got " << str(f);
}

TEST(Task1_2_SpringDamping, IgnoresMotionAcrossTheSpring) {
    const Vec3 f = springDampingForce(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(0, 5, -2), 3.0);
    EXPECT_LESS(f.norm(), 1e-12) << "the damping force on p1 moving across the spring (velocity (0, 5, -2) perpendicular to "
                                    "p1 - p0 = (1, 0, 0)): a damper along the spring must not resist it, so it must vanish; got "
                                 << str(f);
}

TEST(Task1_2_SpringDamping, CoincidentPointsGiveZeroNotNaN) {
    const Vec3 f = springDampingForce(Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(0, 0, 0), Vec3(1, 0, 0), 2.0);
    EXPECT_TRUE(f.allFinite() && f.norm() < 1e-12)
        << "the damping force on p1 for coincident points p0 == p1: the direction is undefined, so the header requires the "
           "zero vector (finite, |f| < 1e-12); got " << str(f);
}

TEST(Task1_2_SpringDamping, RemovesEnergyFromAnOscillation) {
    // A damped spring, integrated with the framework's RK4: the amplitude decays as e^(-kd t / 2m).
    const double k = 100.0, kd = 2.0, m = 1.0;
    Matrix3X x(3, 2), v = Matrix3X::Zero(3, 2);
    x << 0, 1.5, 0, 0, 0, 0;
    VectorX w(2);
    w << 0.0, 1.0 / m;
    ForceField field = [&](const Matrix3X& xs, const Matrix3X& vs, Matrix3X& f) {
        f.setZero(3, 2);
        const Vec3 s = -k * ((xs.col(1) - xs.col(0)).norm() - 1.0) * (xs.col(1) - xs.col(0)).normalized();
        const Vec3 d = springDampingForce(xs.col(0), xs.col(1), vs.col(0), vs.col(1), kd);
        f.col(1) += s + d;
        f.col(0) -= s + d;
    };
    for (int i = 0; i < 2000; ++i) rk4Step(x, v, w, field, 1e-3);  // 2 s
    const double expected = 0.5 * std::exp(-kd / (2 * m) * 2.0);   // 0.0677 m
    const double stretch = x(0, 1) - 1.0, omega_d = std::sqrt(k / m - 1.0);
    const double amplitude = std::hypot(stretch, (v(0, 1) + kd / (2 * m) * stretch) / omega_d);
    EXPECT_CLOSE(amplitude, expected, 0.02 * expected)
        << "the amplitude of a damped spring (k = 100, kd = 2, m = 1, RK4) after 2 s: a damper removes energy, so it must have "
           "decayed from 0.5 m as e^(-kd t / 2m) to "
        << expected << " m; got " << amplitude << " m";
}

// ================================ Task 1.3: explicit Euler ==================================

TEST(Task1_3_ExplicitEuler, OneStepFollowsTheFormula) {
    OneStep s;
    const Vec3 x0 = s.x.col(0), v0 = s.v.col(0);
    explicitEulerStep(s.x, s.v, s.w, s.field, 0.1);
    const Vec3 x1 = x0 + 0.1 * v0, v1 = v0 + 0.1 * 0.5 * s.force(x0, v0);
    EXPECT_TRUE(s.x.col(0).isApprox(x1, 1e-12))
        << "the position of particle 0 after one explicit Euler step (dt = 0.1): explicit Euler moves with the velocity of the "
           "start of the step, so it must be " << str(x1) << "; got " << str(s.x.col(0));
    EXPECT_TRUE(s.v.col(0).isApprox(v1, 1e-12))
        << "the velocity of particle 0 after one explicit Euler step (dt = 0.1, w = 0.5): explicit Euler accelerates with the "
           "force at the start of the step, so it must be " << str(v1) << "; got " << str(s.v.col(0));
}

TEST(Task1_3_ExplicitEuler, PinnedParticleStaysPut) {
    EXPECT_TRUE(pinnedStaysPut(&explicitEulerStep)) << "(the position of the pinned particle 1 over 10 explicit Euler steps)";
}

TEST(Task1_3_ExplicitEuler, PeriodMatchesAnalyticAtSmallStep) {
    double period, amplitude;
    periodAndAmplitude(&explicitEulerStep, 1e-4, &period, &amplitude);
    EXPECT_CLOSE(period, 2 * kPi / 10.0, 0.01 * 2 * kPi / 10.0)
        << "the period of the oscillator m = 1 kg, k = 100 N/m with explicit Euler at dt = 1e-4 s, in s: it must be "
           "2 pi sqrt(m/k) = 0.628 s (1 %)";
    EXPECT_CLOSE(amplitude, 1.0, 0.02) << "the amplitude of the oscillator (released at 1 m) with explicit Euler at dt = 1e-4 s, "
                                          "in m: over 3 periods at so small a step it must stay 1 m (2 %)";
}

TEST(Task1_3_ExplicitEuler, ConvergesWithOrderOne) {
    const double order = measuredOrder(&explicitEulerStep);
    EXPECT_CLOSE(order, 1.0, 0.2) << "the convergence order of explicit Euler, measured from the errors at dt = 2, 1, 0.5 ms: "
                                     "a first-order method halves its error when dt halves, order 1 (± 0.2)";
}

TEST(Task1_3_ExplicitEuler, EnergyGrowsOnUndampedOscillator) {
    double maxEnergyChange, energyRatio;
    energyBehaviour(&explicitEulerStep, 0.01, 10.0, &maxEnergyChange, &energyRatio);
    EXPECT_GREATER(energyRatio, 2.0)
        << "the energy ratio E/E0 of the undamped oscillator after 10 periods of explicit Euler at omega dt = 0.1: explicit "
           "Euler takes both derivatives at the start of the step and gains energy every step, so after 628 steps the energy "
           "must have more than doubled";
}

// =============================== Task 1.4: symplectic Euler =================================

TEST(Task1_4_SymplecticEuler, OneStepFollowsTheFormula) {
    OneStep s;
    const Vec3 x0 = s.x.col(0), v0 = s.v.col(0);
    symplecticEulerStep(s.x, s.v, s.w, s.field, 0.1);
    const Vec3 v1 = v0 + 0.1 * 0.5 * s.force(x0, v0), x1 = x0 + 0.1 * v1;
    EXPECT_TRUE(s.v.col(0).isApprox(v1, 1e-12))
        << "the velocity of particle 0 after one symplectic Euler step (dt = 0.1, w = 0.5): it accelerates with the force at the "
           "start of the step, so it must be " << str(v1) << "; got " << str(s.v.col(0));
    EXPECT_TRUE(s.x.col(0).isApprox(x1, 1e-12))
        << "the position of particle 0 after one symplectic Euler step (dt = 0.1): symplectic Euler moves with the velocity of "
           "the end of the step, so it must be " << str(x1) << "; got " << str(s.x.col(0));
}

TEST(Task1_4_SymplecticEuler, PinnedParticleStaysPut) {
    EXPECT_TRUE(pinnedStaysPut(&symplecticEulerStep)) << "(the position of the pinned particle 1 over 10 symplectic Euler steps)";
}

TEST(Task1_4_SymplecticEuler, PeriodAndAmplitudeMatchAnalytic) {
    double period, amplitude;
    periodAndAmplitude(&symplecticEulerStep, 1e-3, &period, &amplitude);
    EXPECT_CLOSE(period, 2 * kPi / 10.0, 0.005 * 2 * kPi / 10.0)
        << "the period of the oscillator m = 1 kg, k = 100 N/m with symplectic Euler at dt = 1e-3 s, in s: it must be "
           "2 pi sqrt(m/k) = 0.628 s (0.5 %)";
    EXPECT_CLOSE(amplitude, 1.0, 0.01) << "the amplitude of the oscillator (released at 1 m) with symplectic Euler at dt = 1e-3 s, "
                                          "in m: a symplectic method neither gains nor loses energy over time, so it must stay 1 m (1 %)";
}

TEST(Task1_4_SymplecticEuler, ConvergesWithOrderOne) {
    const double order = measuredOrder(&symplecticEulerStep);
    EXPECT_CLOSE(order, 1.0, 0.2) << "the convergence order of symplectic Euler, measured from the errors at dt = 2, 1, 0.5 ms: "
                                     "a first-order method halves its error when dt halves, order 1 (± 0.2)";
}

TEST(Task1_4_SymplecticEuler, EnergyStaysBounded) {
    double maxEnergyChange, energyRatio;
    energyBehaviour(&symplecticEulerStep, 0.01, 50.0, &maxEnergyChange, &energyRatio);
    EXPECT_LESS(maxEnergyChange, 0.15)
        << "the largest relative energy change |E - E0|/E0 of the undamped oscillator over 50 periods of symplectic Euler at "
           "omega dt = 0.1: its energy oscillates but does not drift, so it must stay below 15 %; it reached "
        << 100 * maxEnergyChange << " %";
}

// ================================ Task 1.5: velocity Verlet =================================

TEST(Task1_5_VelocityVerlet, OneStepFollowsTheFormula) {
    OneStep s;
    const Vec3 x0 = s.x.col(0), v0 = s.v.col(0);
    velocityVerletStep(s.x, s.v, s.w, s.field, 0.1);
    const Vec3 vh = v0 + 0.05 * 0.5 * s.force(x0, v0), x1 = x0 + 0.1 * vh, v1 = vh + 0.05 * 0.5 * s.force(x1, vh);
    EXPECT_TRUE(s.x.col(0).isApprox(x1, 1e-12))
        << "the position of particle 0 after one velocity Verlet step (dt = 0.1): it must be " << str(x1)
        << " (Verlet is symmetric: the drift uses the velocity of the middle of the step); got " << str(s.x.col(0));
    EXPECT_TRUE(s.v.col(0).isApprox(v1, 1e-12))
        << "the velocity of particle 0 after one velocity Verlet step (dt = 0.1, w = 0.5): it must be " << str(v1)
        << " (Verlet is symmetric: half the step's impulse from the force at the start, half from the force at the end); got "
        << str(s.v.col(0));
}

TEST(Task1_5_VelocityVerlet, PinnedParticleStaysPut) {
    EXPECT_TRUE(pinnedStaysPut(&velocityVerletStep)) << "(the position of the pinned particle 1 over 10 velocity Verlet steps)";
}

TEST(Task1_5_VelocityVerlet, PeriodAndAmplitudeMatchAnalytic) {
    double period, amplitude;
    periodAndAmplitude(&velocityVerletStep, 1e-3, &period, &amplitude);
    EXPECT_CLOSE(period, 2 * kPi / 10.0, 0.001 * 2 * kPi / 10.0)
        << "the period of the oscillator m = 1 kg, k = 100 N/m with velocity Verlet at dt = 1e-3 s, in s: it must be "
           "2 pi sqrt(m/k) = 0.628 s (0.1 %)";
    EXPECT_CLOSE(amplitude, 1.0, 0.001) << "the amplitude of the oscillator (released at 1 m) with velocity Verlet at dt = 1e-3 s, "
                                           "in m: a second-order symplectic method must keep it at 1 m (0.1 %)";
}

TEST(Task1_5_VelocityVerlet, ConvergesWithOrderTwo) {
    const double order = measuredOrder(&velocityVerletStep);
    EXPECT_CLOSE(order, 2.0, 0.2) << "the convergence order of velocity Verlet, measured from the errors at dt = 2, 1, 0.5 ms: "
                                     "a second-order method quarters its error when dt halves, order 2 (± 0.2)";
}

TEST(Task1_5_VelocityVerlet, EnergyStaysBounded) {
    double maxEnergyChange, energyRatio;
    energyBehaviour(&velocityVerletStep, 0.01, 50.0, &maxEnergyChange, &energyRatio);
    EXPECT_LESS(maxEnergyChange, 0.01)
        << "the largest relative energy change |E - E0|/E0 of the undamped oscillator over 50 periods of velocity Verlet at "
           "omega dt = 0.1: a second-order symplectic method must keep it below 1 %; it reached " << 100 * maxEnergyChange << " %";
}

// ============================ Randomised property tests =======================================
// Random orientations, scales from 1 mm to 100 m, random stiffnesses and masses; seeds 1..kPropertySeeds
// (test_util.h). Expected behaviour from physics: equivariance, energy, momentum.

namespace {
using testing_util::forEachSeed;
using testing_util::RandomGeometry;

// E = k/2 (|p1 - p0| - l0)^2, written here; its central-difference gradient with step h.
Vec3 springEnergyGradient(const Vec3& p0, const Vec3& p1, double k, double l0, double h) {
    auto energy = [&](const Vec3& p) { const double s = (p - p0).norm() - l0; return 0.5 * k * s * s; };
    Vec3 grad;
    for (int a = 0; a < 3; ++a) {
        Vec3 e = Vec3::Zero();
        e[a] = h;
        grad[a] = (energy(p1 + e) - energy(p1 - e)) / (2 * h);
    }
    return grad;
}
}  // namespace

TEST(Task1_1_HookeForce, RandomOrientationsScalesAndStiffnesses) {
    // Hooke's force is the negative gradient of the spring energy (finite differences), whatever the
    // orientation and size of the spring; making the spring s times larger makes the force s times larger.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const double s = G.scale(), k = G.logUniform(1.0, 1e4);
        const Eigen::Matrix3d R = G.rotation();
        const Vec3 u = G.unitVector(), t = G.point(10.0);
        const double len = G.uniform(0.1, 3.0), l0 = G.uniform(0.1, 3.0);  // at unit scale
        const Vec3 a = G.point(1.0), b = a + len * u;
        const Vec3 p0 = R * (s * a) + s * t, p1 = R * (s * b) + s * t;  // rotated, scaled, moved
        const Vec3 f = hookeForce(p0, p1, k, s * l0);
        const Vec3 want = -springEnergyGradient(p0, p1, k, s * l0, 1e-6 * s);
        if (!f.allFinite() || (f - want).norm() > 1e-5 * k * s * std::max(std::abs(len - l0), 0.1))
            return testing::AssertionFailure()
                   << "The spring force must be minus the gradient of the spring energy E = k/2 (|p1-p0| - l0)^2 for a spring "
                      "in any direction and of any size. For p0 = " << str(p0) << ", p1 = " << str(p1) << ", k = " << k
                   << " N/m, l0 = " << s * l0 << " m (length scale " << s << " m) finite differences give " << str(want)
                   << " N, your force is " << str(f) << " N.";
        const Vec3 f1 = hookeForce(a, b, k, l0);  // the same spring, unrotated at unit scale
        if ((f - s * (R * f1)).norm() > 1e-9 * k * s * std::max(std::abs(len - l0), 0.1))
            return testing::AssertionFailure()
                   << "Rotating a spring must rotate its force, and making it " << s << " times larger must make the force "
                   << s << " times larger (Hooke's law has no preferred direction or length scale). Unit-scale spring p0 = " << str(a) << ", p1 = " << str(b)
                   << ", l0 = " << l0 << ": force " << str(f1) << "; rotated and scaled: expected " << str(s * (R * f1))
                   << ", got " << str(f) << ".";
        return testing::AssertionSuccess();
    });
}

TEST(Task1_1_HookeForce, NearlyCoincidentAndNearlyRelaxedSprings) {
    // Two valid near-degenerate springs: end points 1e-9 m to 1e-3 m apart (not coincident), and a
    // spring stretched or compressed by only 1e-9 to 1e-3 of its rest length. Hooke's law holds for
    // both: |F| = k |(|d| - l0)| along the spring.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const double s = G.scale(), k = G.logUniform(1.0, 1e4), l0 = s * G.uniform(0.5, 2.0);
        const Vec3 u = G.unitVector(), p0 = G.point(s);
        const double lens[2] = {G.logUniform(1e-9, 1e-3), l0 * (1.0 + G.sign() * G.logUniform(1e-9, 1e-3))};
        const char* what[2] = {"nearly coincident end points", "a nearly relaxed spring"};
        for (int c = 0; c < 2; ++c) {
            const Vec3 p1 = p0 + lens[c] * u;
            const double len = (p1 - p0).norm();  // after rounding, as the direction (p1 - p0)/len
            const Vec3 f = hookeForce(p0, p1, k, l0), want = -k * (len - l0) * (p1 - p0) / len;
            if (!f.allFinite() || (f - want).norm() > 1e-6 * want.norm())
                return testing::AssertionFailure()
                       << "The force on p1 must follow Hooke's law (stiffness times stretch, along the spring) also for " << what[c]
                       << " (a short spring is still a spring; only exactly coincident points have no direction). p0 = "
                       << str(p0) << ", p1 - p0 = " << str(p1 - p0) << " (|p1-p0| = " << len << " m), l0 = " << l0 << " m, k = " << k
                       << " N/m: expected " << str(want) << " N, got " << str(f) << " N."
                       << (f.allFinite() && f.norm() > 0 ? "" : " An absolute tolerance in metres (e.g. 1e-6) breaks small cloths.");
        }
        return testing::AssertionSuccess();
    });
}

TEST(Task1_2_SpringDamping, RandomOrientationsScalesAndVelocities) {
    // A dashpot only removes energy: its power F.(v1 - v0) = -kd ((v1 - v0).d)^2 <= 0, its force lies along
    // the spring, and it does not depend on the spring's length (1e-9 m to 100 m) or orientation.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const double s = G.scale(), kd = G.logUniform(1e-2, 1e2);
        const Vec3 d = G.unitVector(), p0 = G.point(s);
        const double len = s * G.logUniform(1e-6, 3.0);
        const Vec3 p1 = p0 + len * d;
        const Vec3 vc = G.point(10.0 * s), vr = G.point(10.0 * s);  // common and relative velocity
        const Vec3 f = springDampingForce(p0, p1, vc, vc + vr, kd);
        const Vec3 dir = (p1 - p0).normalized();
        const double power = f.dot(vr), want = -kd * vr.dot(dir) * vr.dot(dir);
        const double tol = 1e-9 * kd * vr.squaredNorm();
        if (!f.allFinite() || std::abs(power - want) > tol || (f - f.dot(dir) * dir).norm() > 1e-9 * kd * vr.norm())
            return testing::AssertionFailure()
                   << "A damper along the spring must act along the spring and only remove energy: its power F.(v1-v0) must be "
                      "-kd ((v1-v0).n)^2 <= 0 with n = (p1-p0)/|p1-p0|, for any spring length and orientation. p0 = " << str(p0) << ", p1 = " << str(p1) << " (length " << len
                   << " m), v0 = " << str(vc) << ", v1 = " << str(vc + vr) << ", kd = " << kd << ": expected power " << want
                   << " W, got " << power << " W from the force " << str(f) << " N.";
        return testing::AssertionSuccess();
    });
}

namespace {
// Four particles with random masses (ratios up to 1e4) joined by six
// springs written here (central forces), at a random scale and orientation.
struct RandomSpringSystem {
    Matrix3X x{3, 4}, v{3, 4};
    VectorX w{4};
    ForceField field;
    explicit RandomSpringSystem(unsigned seed) {
        RandomGeometry G(seed);
        const double s = G.scale();
        const Eigen::Matrix3d R = G.rotation();
        for (int i = 0; i < 4; ++i) {
            x.col(i) = R * G.point(s);
            v.col(i) = G.point(s);
            w[i] = 1.0 / G.logUniform(1e-2, 1e2);
        }
        Eigen::Matrix4d k, l0;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) k(i, j) = G.logUniform(1.0, 1e3), l0(i, j) = s * G.uniform(0.2, 1.5);
        field = [k, l0](const Matrix3X& xs, const Matrix3X&, Matrix3X& f) {
            f.setZero(3, xs.cols());
            for (int i = 0; i < 4; ++i)
                for (int j = i + 1; j < 4; ++j) {
                    const Vec3 d = xs.col(j) - xs.col(i);
                    const Vec3 F = -k(i, j) * (d.norm() - l0(i, j)) * d.normalized();
                    f.col(j) += F, f.col(i) -= F;
                }
        };
    }
    Vec3 momentum() const {
        Vec3 P = Vec3::Zero();
        for (int i = 0; i < 4; ++i)
            if (w[i] > 0) P += v.col(i) / w[i];
        return P;
    }
    Vec3 angularMomentum() const {
        Vec3 L = Vec3::Zero();
        for (int i = 0; i < 4; ++i)
            if (w[i] > 0) L += Vec3(x.col(i)).cross(Vec3(v.col(i))) / w[i];
        return L;
    }
    double momentumScale() const {  // sum of m |v| and of m |x||v|: the size of the rounding errors
        double a = 0;
        for (int i = 0; i < 4; ++i)
            if (w[i] > 0) a += (1.0 + x.col(i).norm()) * v.col(i).norm() / w[i];
        return a;
    }
};

// Ten steps of an integrator on the random spring system: momentum (and, where asked, angular
// momentum) must stay as it was, since the springs are internal central forces.
testing::AssertionResult conservesMomenta(Stepper step, const char* name, unsigned seed, bool angular) {
    RandomSpringSystem S(seed);
    const Vec3 P0 = S.momentum(), L0 = S.angularMomentum();
    const double dt = 1e-3;
    double scale = S.momentumScale();
    for (int n = 0; n < 10; ++n) {
        step(S.x, S.v, S.w, S.field, dt);
        scale = std::max(scale, S.momentumScale());
    }
    if (!S.x.allFinite() || (S.momentum() - P0).norm() > 1e-11 * scale)
        return testing::AssertionFailure()
               << name << " must conserve the total momentum sum m_i v_i of particles joined by springs (internal forces), "
                  "also with very different masses (inverse masses " << str(S.w) << " 1/kg): it went from " << str(P0)
               << " to " << str(S.momentum()) << " kg m/s in 10 steps.";
    if (angular && (S.angularMomentum() - L0).norm() > 1e-11 * scale)
        return testing::AssertionFailure()
               << name << " must conserve the angular momentum sum x_i x m_i v_i of particles joined by springs (central "
                  "forces): it went from " << str(L0) << " to " << str(S.angularMomentum()) << " kg m^2/s in 10 steps "
               << "(inverse masses " << str(S.w) << " 1/kg).";
    return testing::AssertionSuccess();
}
}  // namespace

TEST(Task1_3_ExplicitEuler, ConservesMomentumWithRandomMasses) {
    forEachSeed([](unsigned seed) { return conservesMomenta(&explicitEulerStep, "Explicit Euler", seed, false); });
}

TEST(Task1_4_SymplecticEuler, ConservesMomentumAndAngularMomentumWithRandomMasses) {
    // Symplectic Euler conserves angular momentum exactly for central forces: x_{n+1} x v_{n+1} = x_n x v_{n+1}.
    forEachSeed([](unsigned seed) { return conservesMomenta(&symplecticEulerStep, "Symplectic Euler", seed, true); });
}

TEST(Task1_5_VelocityVerlet, ConservesMomentumAndAngularMomentumWithRandomMasses) {
    // For central forces every update of velocity Verlet keeps sum x_i x m_i v_i (the contract in the header).
    forEachSeed([](unsigned seed) { return conservesMomenta(&velocityVerletStep, "Velocity Verlet", seed, true); });
}

// ================================ Experiment (answers.json) ===================================
// The stage's experiment (task sheet, "Experiment"): predict from theory, measure with your own code,
// explain the difference, in exercises/01_hooke/answers.json. This test checks only that the file is
// complete and well formed; the numbers are graded by the instructor.
TEST(Experiments, AnswerFileIsComplete) {
    EXPECT_TRUE(testing_util::answerFileIsComplete("01_hooke", {"energy_drift_dt_1ms", "energy_drift_dt_0_5ms"}, {"energy_drift_dt_1ms", "energy_drift_dt_0_5ms"}));
}
