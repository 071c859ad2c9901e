#include "clothlab/sim/analytic.h"

#include <cmath>

namespace clothlab {
namespace {
// ξ(t) − ξ_eq = e^{−γt} (A·c(t) + B·s(t)) with c, s chosen per damping regime.
struct Modes {
    double gamma, omega;  // decay rate, (damped) angular frequency or (overdamped) spread
    int regime;           // 0 under-, 1 critically, 2 over-damped
};
Modes modes(const DampedOscillator& o) {
    const double gamma = o.c / (2.0 * o.m), w0sq = o.k / o.m;
    const double disc = w0sq - gamma * gamma;
    if (disc > 1e-12 * w0sq) return {gamma, std::sqrt(disc), 0};
    if (disc < -1e-12 * w0sq) return {gamma, std::sqrt(-disc), 2};
    return {gamma, 0.0, 1};
}
}  // namespace

double DampedOscillator::position(double t) const {
    const Modes md = modes(*this);
    const double a = xi0 - xi_eq, e = std::exp(-md.gamma * t);
    if (md.regime == 0) return xi_eq + e * (a * std::cos(md.omega * t) + (u0 + md.gamma * a) / md.omega * std::sin(md.omega * t));
    if (md.regime == 2) return xi_eq + e * (a * std::cosh(md.omega * t) + (u0 + md.gamma * a) / md.omega * std::sinh(md.omega * t));
    return xi_eq + e * (a + (u0 + md.gamma * a) * t);
}

double DampedOscillator::velocity(double t) const {
    const double h = 1e-6 * std::max(1.0, std::abs(t));  // central difference of the closed form
    return (position(t + h) - position(t - h)) / (2.0 * h);
}

double DampedOscillator::period() const { return 2.0 * M_PI * std::sqrt(m / k); }

}  // namespace clothlab
