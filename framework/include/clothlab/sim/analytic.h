/// @file analytic.h
/// @brief Closed-form solutions the tests and reports compare against.
#pragma once
#include "clothlab/core/types.h"

namespace clothlab {

/// The damped harmonic oscillator m ξ'' + c ξ' + k (ξ − ξ_eq) = 0 with ξ(0) = ξ0, ξ'(0) = u0.
/// Under-, critically and over-damped cases are all handled.
struct DampedOscillator {
    double m = 1.0;    ///< mass, kg
    double k = 1.0;    ///< stiffness, N/m (> 0)
    double c = 0.0;    ///< damping, N s/m
    double xi_eq = 0;  ///< equilibrium coordinate, m
    double xi0 = 0;    ///< initial coordinate, m
    double u0 = 0;     ///< initial velocity, m/s

    /// ξ(t), m.
    double position(double t) const;
    /// ξ'(t), m/s.
    double velocity(double t) const;
    /// Undamped period \f$ T = 2\pi\sqrt{m/k} \f$, s.
    double period() const;
};

/// The catenary: the shape of a hanging inextensible chain of arc length s between two anchors
/// (Kettenlinie). In the vertical plane through both anchors, with the horizontal coordinate u from
/// the first anchor towards the second (horizontal distance d) and the height z above the first
/// (the second is v higher): \f$ z(u) = a\,(\cosh((u - u_0)/a) - \cosh(u_0/a)) \f$. The parameter a
/// solves \f$ \sqrt{s^2 - v^2} = 2a \sinh(d / (2a)) \f$ (bisection on log a, the left side falls
/// monotonically in a), and \f$ u_0 = d/2 - a\,\mathrm{artanh}(v/s) \f$.
struct Catenary {
    Vec3 start{0, 0, 0};      ///< first anchor, m
    Vec3 end{1, 0, 0};        ///< second anchor, m
    Vec3 up{0, 1, 0};         ///< unit vector against gravity
    double length = 1.5;      ///< arc length s > |end − start|, m
    double a = 0.0;           ///< catenary parameter, m (set by solve())
    double u0 = 0.0;          ///< horizontal position of the lowest point from `start`, m (set by solve())

    /// Solves for a and u0 (needs a horizontal distance d > 0 and s > |end − start|).
    /// @return false when there is no catenary (anchors vertically above each other, or s too short)
    bool solve();
    /// The point of the curve at horizontal coordinate u ∈ [0, d], m.
    Vec3 at(double u) const;
    /// Shortest distance from x to the curve between the anchors, m (dense polyline, 4000 pieces,
    /// error below 1e-6 of the span for the sag ratios of the scenes).
    double distance(const Vec3& x) const;
};

}  // namespace clothlab
