/// @file strain.h
/// @brief Edge strain: how far the cloth's edges are stretched, the one measure of stretch that every
/// report, study, plot and the app uses, for every method (super-elasticity, Superelastizität, in a
/// mass-spring network; the remaining constraint error in PBD).
#pragma once
#include <vector>

#include <Eigen/Core>

#include "clothlab/core/types.h"

namespace clothlab {

/// Strain statistics over the edges with a positive rest length. Dimensionless fractions
/// (0.1 = 10 %), reported with unit "1".
struct EdgeStrain {
    double max = 0.0;  ///< largest signed strain \f$ \max_e \varepsilon_e \f$ (negative only if every edge is compressed); 0 without edges
    double rms = 0.0;  ///< root mean square \f$ \sqrt{\tfrac1n \sum_e \varepsilon_e^2} \f$
    int count = 0;     ///< number of edges measured (those with l0 > 0)
};

/// Strain \f$ \varepsilon_e = (\|\vec x_j - \vec x_i\| - l_{0,e}) / l_{0,e} \f$ of every edge e = (i, j)
/// with \f$ l_{0,e} > 0 \f$ (positive: stretched, negative: compressed), summarised as signed maximum
/// and RMS. Zero-length edges are skipped (their strain is undefined), so the result is finite
/// for finite positions.
/// @param edges  particle index pairs (i, j)
/// @param rest   rest length l0 of each edge, m (same length as edges)
/// @param x      positions, 3 x N, m
EdgeStrain edgeStrain(const std::vector<Eigen::Vector2i>& edges, const std::vector<double>& rest, const Matrix3X& x);

}  // namespace clothlab
