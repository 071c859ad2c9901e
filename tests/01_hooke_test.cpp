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
        << "p0 = (0,0,0), p1 = (2,0,0), k = 10, l0 = 1: the spring is stretched by 1, so the force on p1 must be "
           "(-10, 0, 0) (towards p0). Got " << str(f) << ". Check the sign of F = -k (|p1-p0| - l0) (p1-p0)/|p1-p0|.";
}

TEST(Task1_1_HookeForce, PushesApartWhenCompressed) {
    const Vec3 f = hookeForce(Vec3(0, 0, 0), Vec3(0, 0.5, 0), 10.0, 1.0);
    EXPECT_TRUE(f.isApprox(Vec3(0, 5, 0), 1e-12))
        << "p1 = (0,0.5,0) is 0.5 closer than the rest length 1: the force on p1 must push it away from p0, "
           "(0, 5, 0). Got " << str(f) << ". Is the rest length l0 used?";
}

TEST(Task1_1_HookeForce, MagnitudeIsStiffnessTimesStretch) {
    const Vec3 p0(1, 2, 3), dir = Vec3(2, -1, 2) / 3.0;  // unit vector
    const Vec3 f = hookeForce(p0, p0 + 3.0 * dir, 7.0, 1.0);
    EXPECT_NEAR(f.norm(), 7.0 * 2.0, 1e-9)
        << "|p1 - p0| = 3, l0 = 1, k = 7: |F| must be k * 2 = 14, got " << f.norm()
        << ". Did you divide by |p1 - p0| to get a unit direction?";
    EXPECT_TRUE(f.normalized().isApprox(-dir, 1e-9)) << "F must point from p1 towards p0 along the spring; got " << str(f);
}

TEST(Task1_1_HookeForce, ZeroAtRestLength) {
    const Vec3 f = hookeForce(Vec3(1, 1, 1), Vec3(1, 1, 1) + Vec3(0.6, 0, 0.8), 50.0, 1.0);
    EXPECT_LT(f.norm(), 1e-12) << "at rest length the force must vanish; got " << str(f);
}

TEST(Task1_1_HookeForce, NewtonsThirdLaw) {
    const Vec3 a(0.1, -0.4, 2.0), b(1.5, 0.3, -0.7);
    const Vec3 fb = hookeForce(a, b, 12.0, 0.8), fa = hookeForce(b, a, 12.0, 0.8);
    EXPECT_TRUE((fa + fb).norm() < 1e-12 && fb.norm() > 1.0)
        << "swapping the end points must give the opposite force (actio = reactio): F(a,b) = " << str(fb)
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
    EXPECT_TRUE(f.isApprox(-grad, 1e-6)) << "F must equal -grad E with E = k/2 (|p1-p0| - l0)^2; finite differences give "
                                         << str(-grad) << ", your force is " << str(f);
}

TEST(Task1_1_HookeForce, CoincidentPointsGiveZeroNotNaN) {
    const Vec3 f = hookeForce(Vec3(1, 2, 3), Vec3(1, 2, 3), 100.0, 1.0);
    EXPECT_TRUE(f.allFinite()) << "p0 == p1 must not give NaN (division by |p1 - p0| = 0); got " << str(f);
    EXPECT_LT(f.norm(), 1e-12) << "p0 == p1: the direction is undefined, return the zero vector; got " << str(f);
}

// ============================ Task 1.2: damping along the spring ============================

TEST(Task1_2_SpringDamping, OpposesRelativeVelocityAlongSpring) {
    const Vec3 f = springDampingForce(Vec3(0, 0, 0), Vec3(0, 0, 2), Vec3(0, 0, 0), Vec3(0, 0, 3), 0.5);
    EXPECT_TRUE(f.isApprox(Vec3(0, 0, -1.5), 1e-12))
        << "p1 moves away from p0 with 3 m/s along the spring, kd = 0.5: the damping force on p1 must be (0, 0, -1.5); got "
        << str(f);
}

TEST(Task1_2_SpringDamping, UsesRelativeVelocityOnly) {
    const Vec3 v(0.3, -2.0, 1.0);
    const Vec3 f = springDampingForce(Vec3(0, 0, 0), Vec3(1, 1, 0), v, v, 4.0);
    EXPECT_LT(f.norm(), 1e-12) << "both ends moving with the same velocity: no damping; got " << str(f);
}

TEST(Task1_2_SpringDamping, IgnoresMotionAcrossTheSpring) {
    const Vec3 f = springDampingForce(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(0, 5, -2), 3.0);
    EXPECT_LT(f.norm(), 1e-12) << "motion perpendicular to the spring must not be damped; got " << str(f);
}

TEST(Task1_2_SpringDamping, CoincidentPointsGiveZeroNotNaN) {
    const Vec3 f = springDampingForce(Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(0, 0, 0), Vec3(1, 0, 0), 2.0);
    EXPECT_TRUE(f.allFinite() && f.norm() < 1e-12) << "p0 == p1 must give the zero vector, got " << str(f);
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
    EXPECT_NEAR(amplitude, expected, 0.02 * expected)
        << "after 2 s the amplitude of a spring with k = 100, kd = 2, m = 1 must have decayed from 0.5 m to "
        << expected << " m; got " << amplitude << " m";
}

// ================================ Task 1.3: explicit Euler ==================================

TEST(Task1_3_ExplicitEuler, OneStepFollowsTheFormula) {
    OneStep s;
    const Vec3 x0 = s.x.col(0), v0 = s.v.col(0);
    explicitEulerStep(s.x, s.v, s.w, s.field, 0.1);
    const Vec3 x1 = x0 + 0.1 * v0, v1 = v0 + 0.1 * 0.5 * s.force(x0, v0);
    EXPECT_TRUE(s.x.col(0).isApprox(x1, 1e-12)) << "x must become x + dt v_old = " << str(x1) << ", got " << str(s.x.col(0));
    EXPECT_TRUE(s.v.col(0).isApprox(v1, 1e-12)) << "v must become v + dt w F(x_old, v_old) = " << str(v1) << ", got " << str(s.v.col(0));
}

TEST(Task1_3_ExplicitEuler, PinnedParticleStaysPut) { EXPECT_TRUE(pinnedStaysPut(&explicitEulerStep)); }

TEST(Task1_3_ExplicitEuler, PeriodMatchesAnalyticAtSmallStep) {
    double T, A;
    periodAndAmplitude(&explicitEulerStep, 1e-4, &T, &A);
    EXPECT_NEAR(T, 2 * kPi / 10.0, 0.01 * 2 * kPi / 10.0) << "period of m = 1, k = 100 must be 2 pi sqrt(m/k) = 0.628 s";
    EXPECT_NEAR(A, 1.0, 0.02) << "amplitude must stay about 1 m at dt = 1e-4 s";
}

TEST(Task1_3_ExplicitEuler, ConvergesWithOrderOne) {
    const double p = measuredOrder(&explicitEulerStep);
    EXPECT_NEAR(p, 1.0, 0.2) << "halving dt must halve the error (order 1); measured order " << p;
}

TEST(Task1_3_ExplicitEuler, EnergyGrowsOnUndampedOscillator) {
    double worst, ratio;
    energyBehaviour(&explicitEulerStep, 0.01, 10.0, &worst, &ratio);
    EXPECT_GT(ratio, 2.0) << "explicit Euler multiplies the amplitude by sqrt(1 + omega^2 dt^2) every step: after 10 periods "
                             "at omega dt = 0.1 the energy must have grown a lot (theory: 1.01^628 = 517); E/E0 = " << ratio;
}

// =============================== Task 1.4: symplectic Euler =================================

TEST(Task1_4_SymplecticEuler, OneStepFollowsTheFormula) {
    OneStep s;
    const Vec3 x0 = s.x.col(0), v0 = s.v.col(0);
    symplecticEulerStep(s.x, s.v, s.w, s.field, 0.1);
    const Vec3 v1 = v0 + 0.1 * 0.5 * s.force(x0, v0), x1 = x0 + 0.1 * v1;
    EXPECT_TRUE(s.v.col(0).isApprox(v1, 1e-12)) << "v must become v + dt w F(x, v) = " << str(v1) << ", got " << str(s.v.col(0));
    EXPECT_TRUE(s.x.col(0).isApprox(x1, 1e-12)) << "x must become x + dt v_NEW = " << str(x1) << ", got " << str(s.x.col(0));
}

TEST(Task1_4_SymplecticEuler, PinnedParticleStaysPut) { EXPECT_TRUE(pinnedStaysPut(&symplecticEulerStep)); }

TEST(Task1_4_SymplecticEuler, PeriodAndAmplitudeMatchAnalytic) {
    double T, A;
    periodAndAmplitude(&symplecticEulerStep, 1e-3, &T, &A);
    EXPECT_NEAR(T, 2 * kPi / 10.0, 0.005 * 2 * kPi / 10.0) << "period must be 2 pi sqrt(m/k) = 0.628 s";
    EXPECT_NEAR(A, 1.0, 0.01) << "amplitude must stay 1 m";
}

TEST(Task1_4_SymplecticEuler, ConvergesWithOrderOne) {
    const double p = measuredOrder(&symplecticEulerStep);
    EXPECT_NEAR(p, 1.0, 0.2) << "symplectic Euler is first order; measured order " << p;
}

TEST(Task1_4_SymplecticEuler, EnergyStaysBounded) {
    double worst, ratio;
    energyBehaviour(&symplecticEulerStep, 0.01, 50.0, &worst, &ratio);
    EXPECT_LT(worst, 0.15) << "symplectic Euler's energy oscillates but does not drift: over 50 periods at omega dt = 0.1 "
                              "|E - E0|/E0 must stay below 15 %; it reached " << 100 * worst << " %";
}

// ================================ Task 1.5: velocity Verlet =================================

TEST(Task1_5_VelocityVerlet, OneStepFollowsTheFormula) {
    OneStep s;
    const Vec3 x0 = s.x.col(0), v0 = s.v.col(0);
    velocityVerletStep(s.x, s.v, s.w, s.field, 0.1);
    const Vec3 vh = v0 + 0.05 * 0.5 * s.force(x0, v0), x1 = x0 + 0.1 * vh, v1 = vh + 0.05 * 0.5 * s.force(x1, vh);
    EXPECT_TRUE(s.x.col(0).isApprox(x1, 1e-12)) << "x must become x + dt v_half = " << str(x1) << ", got " << str(s.x.col(0));
    EXPECT_TRUE(s.v.col(0).isApprox(v1, 1e-12)) << "v must become v_half + dt/2 w F(x_new, v_half) = " << str(v1) << ", got "
                                                << str(s.v.col(0));
}

TEST(Task1_5_VelocityVerlet, PinnedParticleStaysPut) { EXPECT_TRUE(pinnedStaysPut(&velocityVerletStep)); }

TEST(Task1_5_VelocityVerlet, PeriodAndAmplitudeMatchAnalytic) {
    double T, A;
    periodAndAmplitude(&velocityVerletStep, 1e-3, &T, &A);
    EXPECT_NEAR(T, 2 * kPi / 10.0, 0.001 * 2 * kPi / 10.0) << "period must be 2 pi sqrt(m/k) = 0.628 s";
    EXPECT_NEAR(A, 1.0, 0.001) << "amplitude must stay 1 m";
}

TEST(Task1_5_VelocityVerlet, ConvergesWithOrderTwo) {
    const double p = measuredOrder(&velocityVerletStep);
    EXPECT_NEAR(p, 2.0, 0.2) << "velocity Verlet is second order: halving dt must quarter the error; measured order " << p;
}

TEST(Task1_5_VelocityVerlet, EnergyStaysBounded) {
    double worst, ratio;
    energyBehaviour(&velocityVerletStep, 0.01, 50.0, &worst, &ratio);
    EXPECT_LT(worst, 0.01) << "Verlet's energy error at omega dt = 0.1 stays below 1 %; it reached " << 100 * worst << " %";
}
