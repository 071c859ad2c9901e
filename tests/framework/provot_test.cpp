// Provot's strain limit (sim/provot.h): the pass loop that only re-reads springs at moved particles
// against the plain loop of the header (every spring in every pass), bit for bit.
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "clothlab/io/scene_json.h"
#include "clothlab/sim/mass_spring.h"
#include "clothlab/sim/provot.h"
#include "clothlab/sim/simulation.h"

using namespace clothlab;

namespace {
// The header's passes as written there: Gauss–Seidel over all springs until none exceeds the limit
// by more than 10⁻⁶ (relative), at most max_passes.
int plainProvot(const std::vector<Spring>& springs, Matrix3X& x, Matrix3X& v, const VectorX& w, double tau, double dt,
                int max_passes) {
    int pass = 0;
    while (pass < max_passes) {
        ++pass;
        bool all_within = true;
        for (const Spring& s : springs) {
            const double w_sum = w[s.i] + w[s.j];
            if (!(s.l0 > 0.0) || w_sum == 0.0) continue;
            const Vec3 d = x.col(s.j) - x.col(s.i);
            const double l_max = (1.0 + tau) * s.l0;
            if (d.squaredNorm() <= l_max * l_max) continue;
            const double l = d.norm();
            if (l > l_max * (1.0 + 1e-6)) all_within = false;
            const Vec3 shift = (l - l_max) / l * d;
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

// Both loops on copies of (x, v): the same passes and the same x and v, bit for bit.
void expectSame(const std::vector<Spring>& springs, const Matrix3X& x, const Matrix3X& v, const VectorX& w, double tau,
                int max_passes, int* passes = nullptr) {
    Matrix3X x1 = x, v1 = v, x2 = x, v2 = v;
    const int n1 = plainProvot(springs, x1, v1, w, tau, 1e-3, max_passes);
    const int n2 = applyProvotConstraint(springs, x2, v2, w, tau, 1e-3, max_passes);
    EXPECT_EQ(n1, n2);
    EXPECT_TRUE(x1 == x2) << "largest difference " << (x1 - x2).cwiseAbs().maxCoeff() << " m";
    EXPECT_TRUE(v1 == v2) << "largest difference " << (v1 - v2).cwiseAbs().maxCoeff() << " m/s";
    if (passes) *passes = n1;
}
}  // namespace

// The soft cloth of mfn_provot.json without the limit stretches far beyond τ = 10 % (super-elastic);
// every 50 steps of its fall both loops correct it alike, with the scene's 50 passes and with fewer.
TEST(Provot, SkippingUnmovedSpringsEqualsFullPasses) {
    Scene s = loadScene(std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/mfn_provot.json");
    s.provot.enabled = false;
    auto sim = makeSimulation(s);
    const auto& springs = dynamic_cast<const MassSpringSimulation&>(*sim).springs();
    int most = 0;
    for (int step = 1; step <= 1000; ++step) {
        sim->step();
        if (step % 50) continue;
        const State& st = sim->state();
        int passes = 0;
        expectSame(springs, st.x, st.v, st.w, 0.1, 50, &passes);
        most = std::max(most, passes);
        expectSame(springs, st.x, st.v, st.w, 0.1, 3);
        expectSame(springs, st.x, st.v, st.w, 0.02, 50);
    }
    EXPECT_GT(most, 10) << "the stretched cloth needs many passes (else the test shows little)";
}

// Random masses (some pinned) and a randomly crumpled and stretched cloth.
TEST(Provot, SkippingUnmovedSpringsEqualsFullPassesOnRandomCloth) {
    Scene s = loadScene(std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/mfn_provot.json");
    auto sim = makeSimulation(s);
    const auto& springs = dynamic_cast<const MassSpringSimulation&>(*sim).springs();
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 5; ++trial) {
        State st = sim->state();
        for (int i = 0; i < st.size(); ++i) {
            st.x.col(i) = 1.3 * st.x.col(i) + 0.03 * Vec3(u(rng), u(rng), u(rng));
            st.w[i] = u(rng) < -0.9 ? 0.0 : std::pow(10.0, 2.0 * u(rng));
        }
        expectSame(springs, st.x, Matrix3X::Zero(3, st.size()), st.w, 0.1, 50);
    }
}
