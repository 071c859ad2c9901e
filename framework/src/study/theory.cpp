#include "clothlab/study/theory.h"

#include <cmath>
#include <limits>
#include <random>

#include <Eigen/Eigenvalues>

#include "clothlab/core/input_error.h"
#include "clothlab/sim/implicit_euler.h"
#include "clothlab/sim/mass_spring.h"

namespace clothlab {
namespace {
MassSpringModel modelOf(const Scene& scene) {
    if (scene.model == Model::Spring) return makeSingleSpring(scene.spring);
    if (scene.model == Model::Chain) return makeChain(scene.chain);
    return makeCloth(scene);
}
}  // namespace

double maxAngularFrequency(const Scene& scene) {
    const MassSpringModel m = modelOf(scene);
    const int n = m.state.size();
    std::vector<int> index(static_cast<size_t>(n), -1);
    std::vector<double> inv_sqrt_mass;
    int rows = 0;
    for (int i = 0; i < n; ++i)
        if (m.state.w[i] > 0.0) {
            index[static_cast<size_t>(i)] = 3 * rows++;
            for (int k = 0; k < 3; ++k) inv_sqrt_mass.push_back(std::sqrt(m.state.w[i]));
        }
    if (rows == 0 || m.springs.empty()) return 0.0;
    std::vector<Eigen::Triplet<double>> kt, dt;
    addSpringJacobians(m.springs, m.state.x, index, kt, dt);
    // S = M^{-1/2} K M^{-1/2} with K = -df/dx: symmetric, same eigenvalues as M^{-1} K.
    for (auto& t : kt) t = {t.row(), t.col(), -t.value() * inv_sqrt_mass[static_cast<size_t>(t.row())] * inv_sqrt_mass[static_cast<size_t>(t.col())]};
    SparseMatrix S(3 * rows, 3 * rows);
    S.setFromTriplets(kt.begin(), kt.end());
    double lambda = 0.0;
    if (3 * rows <= 900) {
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Eigen::MatrixXd(S), Eigen::EigenvaluesOnly);
        lambda = es.eigenvalues().maxCoeff();
    } else {  // power iteration; the Rayleigh quotient approaches λ_max from below
        std::mt19937 rng(1);
        std::normal_distribution<double> normal;
        VectorX q = VectorX::NullaryExpr(3 * rows, [&] { return normal(rng); }).normalized();
        for (int it = 0; it < 5000; ++it) {
            const VectorX z = S * q;
            const double next = q.dot(z), norm = z.norm();
            if (norm == 0.0) break;
            q = z / norm;
            const bool converged = it > 50 && std::abs(next - lambda) < 1e-7 * std::abs(next);
            lambda = next;
            if (converged) break;
        }
    }
    return std::sqrt(std::max(0.0, lambda));
}

double theoreticalCriticalDt(Method method, double omega) {
    switch (method) {
        case Method::SymplecticEuler:
        case Method::VelocityVerlet: return 2.0 / omega;
        case Method::Rk4: return 2.0 * std::sqrt(2.0) / omega;
        case Method::ImplicitEuler: return std::numeric_limits<double>::infinity();
        case Method::ExplicitEuler: return 0.0;
        case Method::Pbd:
        case Method::Xpbd: break;
    }
    return -1.0;
}

double provotCriticalStiffness(double m, double dt) { return m * M_PI * M_PI / (dt * dt); }

double sceneStiffness(const Scene& scene) {
    if (scene.model == Model::Spring) return scene.spring.k;
    if (scene.model == Model::Chain) return scene.chain.k;
    for (const SpringGroup* g : {&scene.springs.structural, &scene.springs.shear, &scene.springs.bending})
        if (g->enabled) return g->k;
    return 0.0;
}

Scene withStiffness(const Scene& scene, double k) {
    Scene s = scene;
    if (s.model == Model::Spring) s.spring.k = k;
    else if (s.model == Model::Chain) s.chain.k = k;
    else {
        const double k_old = sceneStiffness(scene);
        const double factor = k_old > 0.0 ? k / k_old : 1.0;
        for (SpringGroup* g : {&s.springs.structural, &s.springs.shear, &s.springs.bending}) g->k *= factor;
    }
    return s;
}

}  // namespace clothlab
