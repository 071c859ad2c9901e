/// @file spring.h
/// @brief A Hooke spring between two particles (slides: Feder mit Federhärte k und Ruhelänge l0).
#pragma once

namespace clothlab {

/// Kind of spring in a mass-spring network (Masse-Feder-Netzwerk).
enum class SpringType {
    Single,      ///< a lone spring or a chain link (stage 01)
    Structural,  ///< Strukturfeder: grid neighbours
    Shear,       ///< Scherfeder: diagonal neighbours
    Bending      ///< Biegefeder: neighbours two apart
};

/// One spring: particles i and j, stiffness k (N/m), rest length l0 (m), damping kd (N s/m).
struct Spring {
    int i = 0;                            ///< first particle (p0)
    int j = 0;                            ///< second particle (p1)
    double k = 0.0;                       ///< Federhärte k, N/m
    double l0 = 0.0;                      ///< Ruhelänge l0, m
    double kd = 0.0;                      ///< damping along the spring, N s/m
    SpringType type = SpringType::Single; ///< structural, shear, bending or single
};

/// One spring type of the mass-spring network.
struct SpringGroup {
    bool enabled = false;   ///< whether springs of this type exist
    double k = 1000.0;      ///< stiffness, N/m
    double kd = 0.0;        ///< damping along the spring, N s/m
};

/// Springs of the mass-spring network (Strukturfedern, Scherfedern, Biegefedern).
struct ClothSprings {
    SpringGroup structural;  ///< grid neighbours
    SpringGroup shear;       ///< diagonal neighbours
    SpringGroup bending;     ///< neighbours two apart
};

}  // namespace clothlab
