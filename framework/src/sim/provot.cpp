#include "clothlab/sim/provot.h"

namespace clothlab {

int applyProvotConstraint(const std::vector<Spring>& springs, Matrix3X& x, Matrix3X& v, const VectorX& w, double tau,
                          double dt, int max_passes) {
    int pass = 0;
    while (pass < max_passes) {
        ++pass;
        bool all_within = true;
        for (const Spring& s : springs) {
            const double w_sum = w[s.i] + w[s.j];
            if (!(s.l0 > 0.0) || w_sum == 0.0) continue;
            const Vec3 d = x.col(s.j) - x.col(s.i);
            const double l_max = (1.0 + tau) * s.l0;
            if (d.squaredNorm() <= l_max * l_max) continue;  // within the limit (most springs): no square root
            const double l = d.norm();
            if (l > l_max * (1.0 + 1e-6)) all_within = false;
            const Vec3 shift = (l - l_max) / l * d;  // δ d̂
            const Vec3 dxi = (w[s.i] / w_sum) * shift, dxj = -(w[s.j] / w_sum) * shift;
            x.col(s.i) += dxi;
            x.col(s.j) += dxj;
            v.col(s.i) += dxi / dt;
            v.col(s.j) += dxj / dt;
        }
        if (all_within) break;
    }
    return pass;
}

}  // namespace clothlab
