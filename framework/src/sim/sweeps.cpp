#include "clothlab/sim/sweeps.h"

#include "clothlab/exercise/04_distance.h"
#include "clothlab/sim/xpbd.h"

namespace clothlab {
namespace {
/// p_{i_m} += Δp_m for the four particles of a stencil.
void addCorrection(const BendingStencil& s, const BendingCorrection& c, Matrix3X& p) {
    p.col(s.i1) += c.dp1;
    p.col(s.i2) += c.dp2;
    p.col(s.i3) += c.dp3;
    p.col(s.i4) += c.dp4;
}
}  // namespace

void projectDistanceSweep(const std::vector<DistanceLink>& links, const VectorX& w, double k, Matrix3X& p) {
    for (const DistanceLink& L : links) {
        const DistanceCorrection c = projectDistanceConstraint(p.col(L.i), p.col(L.j), w[L.i], w[L.j], L.d, k);
        p.col(L.i) += c.dp1;
        p.col(L.j) += c.dp2;
    }
}

void projectBendingSweep(const std::vector<BendingStencil>& stencils, const VectorX& w, double k, Matrix3X& p) {
    for (const BendingStencil& s : stencils) {
        addCorrection(s, projectBendingConstraint(p.col(s.i1), p.col(s.i2), p.col(s.i3), p.col(s.i4), w[s.i1], w[s.i2],
                                                  w[s.i3], w[s.i4], s.phi0, k),
                      p);
    }
}

void projectDistanceSweepXpbd(const std::vector<DistanceLink>& links, const VectorX& w, double alphaTilde,
                              std::vector<double>& lambda, Matrix3X& p) {
    for (size_t k = 0; k < links.size(); ++k) {
        const DistanceLink& L = links[k];
        const DistanceCorrection c = projectDistanceXpbd(p.col(L.i), p.col(L.j), w[L.i], w[L.j], L.d, alphaTilde, lambda[k]);
        p.col(L.i) += c.dp1;
        p.col(L.j) += c.dp2;
    }
}

void projectBendingSweepXpbd(const std::vector<BendingStencil>& stencils, const VectorX& w, double alphaTilde,
                             std::vector<double>& lambda, Matrix3X& p) {
    for (size_t k = 0; k < stencils.size(); ++k) {
        const BendingStencil& s = stencils[k];
        addCorrection(s, projectBendingXpbd(p.col(s.i1), p.col(s.i2), p.col(s.i3), p.col(s.i4), w[s.i1], w[s.i2],
                                            w[s.i3], w[s.i4], s.phi0, alphaTilde, lambda[k]),
                      p);
    }
}

void projectCollisionSweep(const std::vector<CollisionConstraint>& contacts, const VectorX& w, double h, Matrix3X& p) {
    for (const CollisionConstraint& c : contacts) p.col(c.i) += projectCollisionConstraint(p.col(c.i), w[c.i], h, c);
}

void projectSelfCollisionSweep(const std::vector<DistanceLink>& pairs, const Matrix3X& x, const VectorX& w, double mu,
                               Matrix3X& p) {
    for (const DistanceLink& L : pairs) {
        const double depth = L.d - (p.col(L.i) - p.col(L.j)).norm();
        if (depth <= 0.0) continue;
        const PairCorrection c = projectSeparation(p.col(L.i), p.col(L.j), w[L.i], w[L.j], L.d);
        p.col(L.i) += c.dpi;
        p.col(L.j) += c.dpj;
        if (mu <= 0.0) continue;
        const PairCorrection f = layerFriction(p.col(L.i), p.col(L.j), x.col(L.i), x.col(L.j), w[L.i], w[L.j], mu, depth);
        p.col(L.i) += f.dpi;
        p.col(L.j) += f.dpj;
    }
}

}  // namespace clothlab
