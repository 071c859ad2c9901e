/// @file analytic.h
/// @brief Closed-form solutions the tests and reports compare against.
#pragma once

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

}  // namespace clothlab
