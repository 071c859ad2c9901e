#include "clothlab/sim/strain.h"

#include <algorithm>
#include <cmath>

namespace clothlab {

EdgeStrain edgeStrain(const std::vector<Eigen::Vector2i>& edges, const std::vector<double>& rest, const Matrix3X& x) {
    EdgeStrain s;
    double sum_sq = 0.0;
    for (size_t k = 0; k < edges.size(); ++k) {
        const double l0 = rest[k];
        if (!(l0 > 0.0)) continue;
        const double e = ((x.col(edges[k][1]) - x.col(edges[k][0])).norm() - l0) / l0;
        s.max = s.count == 0 ? e : std::max(s.max, e);
        sum_sq += e * e;
        ++s.count;
    }
    if (s.count > 0) s.rms = std::sqrt(sum_sq / s.count);
    return s;
}

}  // namespace clothlab
