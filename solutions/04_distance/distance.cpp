// Stage 04 — the distance constraint (reference solution).
// Task sheet: exercises/04_distance/README.md
#include <cmath>
#include <vector>

#include "clothlab/exercise/04_distance.h"

namespace clothlab {

// ---- Task 4.1: the cost function ----------------------------------------------
double distanceConstraint(const Vec3& p1, const Vec3& p2, double d) {
    return (p1 - p2).norm() - d;
}

// ---- Task 4.2: its gradient -----------------------------------------------------
Vec3 distanceGradient(const Vec3& p1, const Vec3& p2) {
    const Vec3 e = p1 - p2;
    const double len = e.norm();
    if (len < 1e-12) return Vec3::Zero();  // direction undefined
    return e / len;
}

// ---- Task 4.3: the projection ----------------------------------------------------
DistanceCorrection projectDistanceConstraint(const Vec3& p1, const Vec3& p2, double w1, double w2, double d,
                                             double k) {
    const Vec3 e = p1 - p2;
    const double len = e.norm();
    const double wsum = w1 + w2;
    if (len < 1e-12 || wsum <= 0.0) return {Vec3::Zero(), Vec3::Zero()};  // undefined direction / both pinned
    const Vec3 s = (k * (len - d) / (wsum * len)) * e;  // C n k / (w1 + w2)
    return {-w1 * s, w2 * s};
}

// ---- Bonus 4.4: long-range attachments ------------------------------------------------------------
std::vector<int> tetherAnchors(const Matrix3X& rest, const VectorX& w) {
    const int n = static_cast<int>(rest.cols());
    std::vector<int> anchor(n, -1);
    for (int i = 0; i < n; ++i) {
        if (w[i] == 0.0) continue;  // a pinned particle needs no tether
        double nearest = INFINITY;
        for (int a = 0; a < n; ++a) {
            const double dist = (rest.col(i) - rest.col(a)).norm();
            if (w[a] == 0.0 && dist < nearest) {  // strictly nearer: of equally near pins the lowest index
                nearest = dist;
                anchor[i] = a;
            }
        }
    }
    return anchor;
}

Vec3 projectTether(const Vec3& p, const Vec3& anchor, double L) {
    const Vec3 e = p - anchor;
    const double len = e.norm();
    if (len <= L) return Vec3::Zero();  // slack: the constraint C = len - L <= 0 holds
    return -((len - L) / len) * e;      // onto the sphere of radius L around the anchor
}

}  // namespace clothlab
