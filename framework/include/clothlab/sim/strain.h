/// @file strain.h
/// @brief Spring strain, the measure of super-elasticity (Superelastizität) in a mass-spring network.
#pragma once
#include <vector>

#include "clothlab/core/spring.h"
#include "clothlab/core/types.h"

namespace clothlab {

/// Strain statistics over the springs with a positive rest length.
struct StrainStats {
    double max = 0.0;  ///< largest strain \f$ \max_s (l_s - l_{0,s}) / l_{0,s} \f$ (1 = 100 %), 0 if no spring qualifies
    double rms = 0.0;  ///< root mean square \f$ \sqrt{\tfrac1n \sum_s \varepsilon_s^2} \f$ of the strains
    int count = 0;     ///< number of springs measured (springs with l0 > 0)
};

/// Strain \f$ \varepsilon_s = (\|\vec x_j - \vec x_i\| - l_0) / l_0 \f$ of every spring with l0 > 0
/// (positive: stretched, negative: compressed), summarised as maximum and RMS.
/// Zero-length springs are skipped (their strain is undefined), so the result is always finite
/// for finite positions.
/// @param springs  the springs
/// @param x        positions, 3 x N, m
StrainStats springStrain(const std::vector<Spring>& springs, const Matrix3X& x);

}  // namespace clothlab
