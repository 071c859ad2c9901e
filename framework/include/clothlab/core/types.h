/// @file types.h
/// @brief Basic types of clothlab: particle data lives in flat Eigen arrays.
///
/// Positions and velocities of N particles are stored as 3 x N matrices
/// (one column per particle, metres and metres per second); inverse masses
/// as a vector of length N (1/kg, w = 0 means the particle is pinned).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace clothlab {

/// A point or vector in 3-D space (metres, m/s, newtons, ... as the context says).
using Vec3 = Eigen::Vector3d;
/// 3 x N matrix: column i holds the vector of particle i.
using Matrix3X = Eigen::Matrix3Xd;
/// Vector of N scalars, one per particle.
using VectorX = Eigen::VectorXd;

}  // namespace clothlab
