// Stage 03 — the PBD loop (reference solution).
// Task sheet: exercises/03_pbd_loop/README.md
#include <cmath>

#include <Eigen/Dense>

#include "clothlab/exercise/03_pbd_loop.h"

namespace clothlab {

// ---- Task 3.1: dampVelocities ------------------------------------------------
void dampVelocities(const Matrix3X& x, Matrix3X& v, const VectorX& w, double kDamping) {
    if (kDamping <= 0.0) return;
    const int n = static_cast<int>(x.cols());
    double mass = 0.0;
    Vec3 xcm = Vec3::Zero(), vcm = Vec3::Zero();
    for (int i = 0; i < n; ++i) {
        if (w[i] <= 0.0) continue;  // pinned: infinite mass, not part of the free body
        const double m = 1.0 / w[i];
        mass += m;
        xcm += m * x.col(i);
        vcm += m * v.col(i);
    }
    if (mass <= 0.0) return;
    xcm /= mass;
    vcm /= mass;
    Vec3 L = Vec3::Zero();
    Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
    for (int i = 0; i < n; ++i) {
        if (w[i] <= 0.0) continue;
        const double m = 1.0 / w[i];
        const Vec3 r = x.col(i) - xcm;
        L += r.cross(m * v.col(i));
        I += m * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());  // r~ r~^T
    }
    // Pseudo-inverse: no rotation about an axis with zero moment of inertia.
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(I);
    const double tol = 1e-12 * std::max(1.0, eig.eigenvalues().cwiseAbs().maxCoeff());
    Vec3 omega = Vec3::Zero();
    for (int a = 0; a < 3; ++a)
        if (eig.eigenvalues()[a] > tol)
            omega += eig.eigenvectors().col(a) * (eig.eigenvectors().col(a).dot(L) / eig.eigenvalues()[a]);
    for (int i = 0; i < n; ++i) {
        if (w[i] <= 0.0) continue;
        const Vec3 dv = vcm + omega.cross(x.col(i) - xcm) - v.col(i);
        v.col(i) += kDamping * dv;
    }
}

// ---- Task 3.2: stiffness per iteration ---------------------------------------
double iterationStiffness(double k, int iterations) {
    if (iterations <= 0) return k;
    return 1.0 - std::pow(1.0 - k, 1.0 / iterations);
}

// ---- Task 3.3: one PBD step, lines (5)-(16) ----------------------------------
void pbdStep(PbdParticles& P, const PbdCallbacks& cb, double kDamping, int iterations, double dt) {
    Matrix3X f = Matrix3X::Zero(3, P.x.cols());
    if (cb.externalForces) cb.externalForces(P.x, P.v, f);
    P.v += dt * (f * P.w.asDiagonal());                                   // (5)  v += dt w f_ext
    dampVelocities(P.x, P.v, P.w, kDamping);                              // (6)
    P.p = P.x + dt * P.v;                                                 // (7)  p = x + dt v
    if (cb.generateCollisionConstraints) cb.generateCollisionConstraints(P.x, P.p);  // (8)
    for (int it = 0; it < iterations; ++it)                               // (9)
        if (cb.projectConstraints) cb.projectConstraints(P.p);            // (10)
    P.v = (P.p - P.x) / dt;                                               // (13)
    P.x = P.p;                                                            // (14)
    if (cb.velocityUpdate) cb.velocityUpdate(P.x, P.v);                   // (16)
}

}  // namespace clothlab
