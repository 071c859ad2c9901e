#include "clothlab/sim/strain.h"

#include <algorithm>
#include <cmath>

namespace clothlab {

StrainStats springStrain(const std::vector<Spring>& springs, const Matrix3X& x) {
    StrainStats s;
    double sum_sq = 0.0;
    for (const Spring& sp : springs) {
        if (!(sp.l0 > 0.0)) continue;
        const double e = ((x.col(sp.j) - x.col(sp.i)).norm() - sp.l0) / sp.l0;
        s.max = s.count == 0 ? e : std::max(s.max, e);
        sum_sq += e * e;
        ++s.count;
    }
    if (s.count > 0) s.rms = std::sqrt(sum_sq / s.count);
    return s;
}

}  // namespace clothlab
