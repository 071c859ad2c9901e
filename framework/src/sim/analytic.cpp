#include "clothlab/sim/analytic.h"

#include <algorithm>
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

namespace {
// The horizontal axis of the catenary's plane: the horizontal part of end − start.
Vec3 horizontalOf(const Catenary& c) {
    const Vec3 r = c.end - c.start;
    return r - r.dot(c.up) * c.up;
}
}  // namespace

bool Catenary::solve() {
    const double d = horizontalOf(*this).norm(), v = (end - start).dot(up);
    const double target = std::sqrt(std::max(0.0, length * length - v * v));
    if (!(d > 1e-12) || !(length > (end - start).norm())) return false;
    // f(a) = 2 a sinh(d / (2a)) falls from infinity (a -> 0) to d (a -> infinity): bisection on log a.
    double lo = std::log(d) - 10.0, hi = std::log(d) + 20.0;
    const auto f = [&](double loga) {
        const double aa = std::exp(loga), x = d / (2 * aa);
        return x > 700 ? INFINITY : 2 * aa * std::sinh(x);
    };
    for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) > target ? lo : hi) = mid;
    }
    a = std::exp(0.5 * (lo + hi));
    u0 = d / 2 - a * std::atanh(v / length);
    return true;
}

Vec3 Catenary::at(double u) const {
    const Vec3 h = horizontalOf(*this).normalized();
    return start + u * h + a * (std::cosh((u - u0) / a) - std::cosh(u0 / a)) * up;
}

double Catenary::distance(const Vec3& x) const {
    const double d = horizontalOf(*this).norm();
    const int n = 4000;
    double best = INFINITY;
    Vec3 prev = at(0.0);
    for (int k = 1; k <= n; ++k) {
        const Vec3 next = at(d * k / n), seg = next - prev;
        const double t = std::clamp((x - prev).dot(seg) / seg.squaredNorm(), 0.0, 1.0);
        best = std::min(best, (x - prev - t * seg).norm());
        prev = next;
    }
    return best;
}

}  // namespace clothlab
