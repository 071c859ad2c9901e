/// @file state.h
/// @brief The particle state shared by every simulation method.
#pragma once
#include "clothlab/core/types.h"

namespace clothlab {

/// Particles as flat arrays (slides: x_i, v_i, w_i).
struct State {
    Matrix3X x;      ///< positions x_i, 3 x N, metres
    Matrix3X v;      ///< velocities v_i, 3 x N, m/s
    VectorX w;       ///< inverse masses w_i = 1/m_i, N, 1/kg; w_i = 0: pinned
    double t = 0.0;  ///< simulated time, seconds

    /// Number of particles N.
    int size() const { return static_cast<int>(x.cols()); }
    /// Resizes to N particles at rest at the origin with unit mass.
    void resize(int n) {
        x = Matrix3X::Zero(3, n);
        v = Matrix3X::Zero(3, n);
        w = VectorX::Ones(n);
    }
    /// True if every position, velocity and inverse mass is finite (no NaN, no Inf).
    bool isFinite() const { return x.allFinite() && v.allFinite() && w.allFinite(); }
};

}  // namespace clothlab
