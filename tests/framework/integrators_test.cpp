// The framework's own numerics: the analytic oscillator and RK4 (not graded).
#include <cmath>

#include <gtest/gtest.h>

#include "clothlab/sim/analytic.h"
#include "clothlab/sim/rk4.h"

using namespace clothlab;

TEST(Analytic, DampedOscillatorSolvesItsODE) {
    // m x'' + c x' + k (x - x_eq) = 0 and the initial values, in all three damping regimes.
    for (double c : {0.0, 1.0, 20.0, 50.0}) {
        DampedOscillator o{1.0, 100.0, c, -1.1, -1.5, 0.3};
        EXPECT_NEAR(o.position(0), -1.5, 1e-12) << "c = " << c;
        EXPECT_NEAR(o.velocity(0), 0.3, 1e-6) << "c = " << c;
        for (double t : {0.1, 0.37, 1.2}) {
            const double h = 1e-4;
            const double acc = (o.position(t + h) - 2 * o.position(t) + o.position(t - h)) / (h * h);
            const double residual = o.m * acc + o.c * o.velocity(t) + o.k * (o.position(t) - o.xi_eq);
            EXPECT_NEAR(residual, 0.0, 1e-3) << "c = " << c << ", t = " << t;
        }
    }
}

TEST(Rk4, FourthOrderOnHarmonicOscillator) {
    auto error = [](double dt) {
        Matrix3X x(3, 1), v = Matrix3X::Zero(3, 1);
        x << 1, 0, 0;
        VectorX w = VectorX::Ones(1);
        ForceField f = [](const Matrix3X& xs, const Matrix3X&, Matrix3X& out) { out = -100.0 * xs; };
        const int n = static_cast<int>(std::lround(1.0 / dt));
        for (int i = 0; i < n; ++i) rk4Step(x, v, w, f, dt);
        return std::abs(x(0, 0) - std::cos(10.0));
    };
    const double order = std::log2(error(0.01) / error(0.005));
    EXPECT_NEAR(order, 4.0, 0.15);
}
