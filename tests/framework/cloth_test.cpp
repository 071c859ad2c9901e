// The cloth model, Provot's strain limit and implicit Euler (framework + reference stages, not graded).
#include <cmath>

#include <gtest/gtest.h>

#include "clothlab/io/scene_json.h"
#include "clothlab/sim/implicit_euler.h"
#include "clothlab/sim/mass_spring.h"
#include "clothlab/sim/run.h"
#include "clothlab/sim/strain.h"
#include "clothlab/exercise/02_mfn.h"

using namespace clothlab;

namespace {
Scene scene(const std::string& name, const std::vector<std::string>& sets = {}) {
    return loadScene(std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/" + name, sets);
}
double metric(const Simulation& sim, const std::string& name) {
    for (const Metric& m : sim.metrics()) if (m.name == name) return m.value;
    return NAN;
}
std::vector<std::string> passNames(const Simulation& sim) {
    std::vector<std::string> names;
    for (const auto& p : sim.timer().passes()) names.push_back(p.name);
    return names;
}
}  // namespace

TEST(Cloth, SceneBuildsGridSpringsAndTriangles) {
    auto sim = makeSimulation(scene("mfn_hanging.json"));
    const int nx = 20, ny = 20;
    EXPECT_EQ(sim->state().size(), nx * ny);
    EXPECT_EQ(sim->edges().size(), static_cast<size_t>((nx - 1) * ny + nx * (ny - 1) + 2 * (nx - 1) * (ny - 1) + (nx - 2) * ny + nx * (ny - 2)));
    EXPECT_EQ(sim->triangles().size(), static_cast<size_t>(2 * (nx - 1) * (ny - 1)));
    EXPECT_EQ(sim->state().w[0], 0.0);
    EXPECT_EQ(sim->state().w[nx - 1], 0.0);
    double free_mass = 0.0;
    for (int i = 0; i < nx * ny; ++i) free_mass += sim->state().w[i] > 0 ? 1.0 / sim->state().w[i] : 0.0;
    EXPECT_NEAR(free_mass, 0.4 * (nx * ny - 2) / (nx * ny), 1e-12) << "m_i = m_gesamt / (nx ny), two pinned";
    sim->step();
    EXPECT_EQ(passNames(*sim), (std::vector<std::string>{"forces: gravity + air damping", "forces: springs", "integrate: symplectic_euler"}));
    auto provot = makeSimulation(scene("mfn_provot.json"));
    provot->step();
    EXPECT_EQ(passNames(*provot).back(), "provot: strain limit");
}

TEST(Cloth, HangingSoftClothIsSuperElasticAndProvotLimitsStrain) {
    auto soft = makeSimulation(scene("mfn_hanging.json"));
    auto limited = makeSimulation(scene("mfn_provot.json"));
    double soft_max = 0.0, limited_max = 0.0;
    for (int s = 0; s < 1000; ++s) {
        soft->step();
        limited->step();
        soft_max = std::max(soft_max, metric(*soft, "max_strain"));
        limited_max = std::max(limited_max, metric(*limited, "max_strain"));
    }
    EXPECT_GT(soft_max, 0.20) << "the soft cloth must show super-elasticity (strain as a fraction)";
    EXPECT_LE(limited_max, 0.10 + 0.001) << "Provot: max strain <= tau = 0.1 (+ 0.001 tolerance)";
    EXPECT_GT(limited_max, 0.09) << "the limit is active, not trivially satisfied";
    EXPECT_TRUE(limited->state().isFinite());
    // Pins stay put under the correction.
    EXPECT_NEAR(limited->state().x(0, 0), -0.5, 1e-12);
    EXPECT_NEAR(limited->state().x(1, 19), 0.0, 1e-12);
}

TEST(Strain, MaxAndRmsOfKnownStretches) {
    Matrix3X x(3, 3);
    x.col(0) = Vec3(0, 0, 0), x.col(1) = Vec3(1.2, 0, 0), x.col(2) = Vec3(1.2, -0.9, 0);
    const std::vector<Eigen::Vector2i> edges = {{0, 1}, {1, 2}, {0, 2}};
    const std::vector<double> rest = {1.0, 1.0, 0.0};  // zero rest length: skipped
    const EdgeStrain st = edgeStrain(edges, rest, x);
    EXPECT_EQ(st.count, 2);
    EXPECT_NEAR(st.max, 0.2, 1e-12);
    EXPECT_NEAR(st.rms, std::sqrt((0.04 + 0.01) / 2), 1e-12);
}

TEST(ImplicitEuler, SpringJacobiansMatchFiniteDifferences) {
    // A distorted 3 x 3 cloth: dF/dx and dF/dv of the spring forces against central differences.
    Scene sc = scene("mfn_hanging.json", {"cloth.nx=3", "cloth.ny=3", "cloth.pins=[]", "springs.bending.kd=0.05"});
    MassSpringModel m = makeCloth(sc);
    const int n = m.state.size();
    Matrix3X x = m.state.x, v = Matrix3X::Zero(3, n);
    // dF/dv is exact for the damping along the springs. K leaves out the position derivative of that
    // damping (as Baraff & Witkin do), and clamps compressed springs: K is compared below without
    // damping and with every spring stretched, where it is exact.
    for (int i = 0; i < n; ++i) x.col(i) += Vec3(0.03 * std::sin(i), 0.05 * std::cos(3 * i), 0.04 * std::sin(2 * i + 1)),
                                v.col(i) = Vec3(std::cos(i), 0.5, -std::sin(i));
    std::vector<int> index(n);
    for (int i = 0; i < n; ++i) index[i] = 3 * i;
    std::vector<Eigen::Triplet<double>> kt, dt;
    addSpringJacobians(m.springs, x, index, kt, dt);
    SparseMatrix K(3 * n, 3 * n), D(3 * n, 3 * n);
    K.setFromTriplets(kt.begin(), kt.end());
    D.setFromTriplets(dt.begin(), dt.end());
    auto forces = [&](const Matrix3X& xs, const Matrix3X& vs) {
        Matrix3X f = Matrix3X::Zero(3, n);
        addClothSpringForces(m.springs, xs, vs, f);
        return f;
    };
    const Eigen::MatrixXd Dd(D);
    const double h = 1e-7;
    for (int c = 0; c < 3 * n; ++c) {
        Matrix3X vp = v, vm = v;
        vp(c % 3, c / 3) += h, vm(c % 3, c / 3) -= h;
        const Matrix3X dfv = (forces(x, vp) - forces(x, vm)) / (2 * h);
        for (int r = 0; r < 3 * n; ++r) EXPECT_NEAR(Dd(r, c), dfv(r % 3, r / 3), 1e-5) << "dF/dv(" << r << ", " << c << ")";
    }
    // K against finite differences of forces without damping, all springs stretched.
    for (Spring& s : m.springs) s.kd = 0.0, s.l0 = 0.5 * (x.col(s.j) - x.col(s.i)).norm();
    kt.clear(), dt.clear();
    addSpringJacobians(m.springs, x, index, kt, dt);
    K.setFromTriplets(kt.begin(), kt.end());
    const Eigen::MatrixXd K2(K);
    for (int c = 0; c < 3 * n; ++c) {
        Matrix3X xp = x, xm = x;
        xp(c % 3, c / 3) += h, xm(c % 3, c / 3) -= h;
        const Matrix3X dfx = (forces(xp, v) - forces(xm, v)) / (2 * h);
        for (int r = 0; r < 3 * n; ++r) EXPECT_NEAR(K2(r, c), dfx(r % 3, r / 3), 1e-4 * std::max(1.0, std::abs(K2(r, c)))) << "dF/dx(" << r << ", " << c << ")";
    }
}

TEST(ImplicitEuler, ArtificialDampingIsOneOverOnePlusOmegaSquaredDtSquared) {
    // Undamped single spring: backward Euler scales the oscillation energy by 1/(1 + ω²Δt²) per step.
    const double k = 100.0, m = 1.0, dt = 0.02, omega = std::sqrt(k / m);
    auto sim = makeSimulation(scene("spring.json", {"solver.method=implicit_euler", "solver.dt=0.02"}));
    auto oscillation = [&] {
        const double xi = -sim->state().x(1, 1), xi_eq = 1.0 + m * 9.81 / k, u = -sim->state().v(1, 1);
        return 0.5 * m * u * u + 0.5 * k * (xi - xi_eq) * (xi - xi_eq);
    };
    const double e0 = oscillation(), e_total0 = metric(*sim, "energy");
    for (int s = 0; s < 50; ++s) sim->step();
    EXPECT_NEAR(oscillation() / e0, std::pow(1.0 + omega * omega * dt * dt, -50), 1e-9);
    EXPECT_LT(metric(*sim, "energy"), e_total0 - 0.5 * e0) << "the energy plot shows the artificial damping";
}

TEST(ImplicitEuler, FirstOrderOnTheSingleSpring) {
    auto err = [](double dt) {
        auto sim = makeSimulation(scene("spring.json", {"solver.method=implicit_euler", "solver.dt=" + std::to_string(dt)}));
        runSimulation(*sim, std::lround(1.0 / dt), std::lround(1.0 / dt));
        return metric(*sim, "error");
    };
    const double e1 = err(2e-3), e2 = err(1e-3);
    EXPECT_NEAR(std::log2(e1 / e2), 1.0, 0.15);
}

TEST(ImplicitEuler, BoundedWhereExplicitMethodsExplode) {
    // Stiff spring, stiff chain, stiff cloth at a time step far beyond omega dt = 2.
    const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
        {"spring.json", {"spring.k=1e6", "solver.dt=0.01"}},
        {"chain.json", {"chain.k=1e7", "solver.dt=0.005"}},
        {"mfn_implicit.json", {"solver.dt=0.02"}},
    };
    for (const auto& [file, sets] : cases) {
        for (const char* method : {"explicit_euler", "symplectic_euler", "velocity_verlet", "rk4"}) {
            auto s = sets;
            s.push_back(std::string("solver.method=") + method);
            auto sim = makeSimulation(scene(file, s));
            EXPECT_TRUE(runSimulation(*sim, 300, 300).unstable) << file << " " << method << " should explode here";
        }
        auto s = sets;
        s.push_back("solver.method=implicit_euler");
        auto sim = makeSimulation(scene(file, s));
        const double e0 = metric(*sim, "energy");
        const RunResult r = runSimulation(*sim, 100, 10);
        EXPECT_FALSE(r.unstable) << file << ": " << r.message;
        for (const ReportRow& row : r.rows) EXPECT_LE(row.metrics[0].value, e0 + 1e-9 * std::abs(e0) + 1e-9) << file << ": energy must not grow";
    }
}

TEST(ImplicitEuler, PinnedParticlesStayPut) {
    auto sim = makeSimulation(scene("mfn_implicit.json", {"solver.dt=0.05"}));
    const Vec3 pin = sim->state().x.col(19);
    for (int s = 0; s < 20; ++s) sim->step();
    EXPECT_TRUE(sim->state().x.col(19).isApprox(pin, 0.0));
    EXPECT_LT(sim->state().x(1, 399), -0.9) << "the free corner hangs down";
}

TEST(ImplicitEuler, ConservesMomentumWithCholeskyAndWithCG) {
    // No pins, no gravity, no air damping: the forces are internal, so sum m_i v_i must not change.
    // 8 x 8 (186 unknowns) is solved by sparse Cholesky, 24 x 24 (1728 unknowns) by conjugate gradients.
    for (int n : {8, 24}) {
        auto sim = makeSimulation(scene("mfn_implicit.json", {"cloth.nx=" + std::to_string(n), "cloth.ny=" + std::to_string(n), "cloth.pins=[]",
                                                             "forces.gravity=[0,0,0]", "forces.air_damping=0", "solver.dt=0.01"}));
        State& s = sim->state();
        for (int i = 0; i < s.size(); ++i) {
            s.x.col(i) += 0.01 * Vec3(std::sin(1.3 * i), std::cos(0.7 * i), std::sin(2.1 * i));
            s.v.col(i) = Vec3(std::cos(0.9 * i), 0.3 * std::sin(1.7 * i), 1.0);
        }
        auto momentum = [&] {
            Vec3 p = Vec3::Zero();
            for (int i = 0; i < s.size(); ++i) p += s.v.col(i) / s.w[i];
            return p;
        };
        const Vec3 p0 = momentum();
        for (int step = 0; step < 10; ++step) sim->step();
        EXPECT_TRUE(s.isFinite());
        EXPECT_LT((momentum() - p0).norm(), 1e-6 * p0.norm()) << n << " x " << n << ": momentum " << momentum().transpose() << " vs " << p0.transpose();
        EXPECT_LT(metric(*sim, "max_strain"), 0.05) << "the stiff springs pulled the disturbed cloth together";
    }
}
