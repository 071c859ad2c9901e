// Graded tests of stage 02 — cloth as a mass-spring network (Masse-Feder-Netzwerk).
// Test names start with the task they check (Task2_1 = exercise 2.1). Points: 02_mfn.points.json.
// Each task is graded on its own: force tests build their springs here, not with your makeClothSprings,
// and integrate with code written here. Task 2.2 calls your stage-01 hookeForce and springDampingForce:
// if stage 01 is unfinished, grade with ./lab grade --stage 02 --reference 01.
#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "clothlab/core/grid.h"
#include "clothlab/exercise/01_hooke.h"
#include "clothlab/exercise/02_mfn.h"
#include "clothlab/sim/energy.h"  // springEnergy(): the framework's, not your code
#include "test_util.h"

using namespace clothlab;

namespace {

using testing_util::str;

// Positions of a vertical nx x ny grid, width x height metres, particle (c, r) at (c dx, -r dy, 0).
Matrix3X gridPositions(int nx, int ny, double width, double height) {
    ClothSpec spec;
    spec.nx = nx, spec.ny = ny, spec.width = width, spec.height = height;
    return makeGridState(spec).x;
}

ClothSprings only(bool structural, bool shear, bool bending) {
    ClothSprings t;
    t.structural = {structural, 100.0, 0.1};
    t.shear = {shear, 50.0, 0.2};
    t.bending = {bending, 10.0, 0.3};
    return t;
}

int countType(const std::vector<Spring>& s, SpringType type) {
    return static_cast<int>(std::count_if(s.begin(), s.end(), [&](const Spring& sp) { return sp.type == type; }));
}

/// "" when every spring says which kind it is, else what is wrong: the tests of 2.1 count, measure
/// and compare the springs per type, so a spring left at Spring::type's default fails all of them.
std::string typeProblem(const std::vector<Spring>& s) {
    for (const Spring& sp : s)
        if (sp.type != SpringType::Structural && sp.type != SpringType::Shear && sp.type != SpringType::Bending)
            return "spring " + std::to_string(sp.i) + "-" + std::to_string(sp.j) + " has type " +
                   (sp.type == SpringType::Single ? std::string("Single (Spring::type's default)") : "value " + std::to_string(static_cast<int>(sp.type))) +
                   ": set Spring::type to SpringType::Structural, Shear or Bending; the counts, rest lengths and "
                   "stiffnesses of these tests are checked per type";
    return "";
}

// The closed-form counts of the task sheet.
int structuralCount(int nx, int ny) { return (nx - 1) * ny + nx * (ny - 1); }
int shearCount(int nx, int ny) { return 2 * (nx - 1) * (ny - 1); }
int bendingCount(int nx, int ny) { return std::max(0, nx - 2) * ny + nx * std::max(0, ny - 2); }

const std::vector<std::pair<int, int>> kSizes = {{2, 2}, {3, 5}, {7, 4}, {10, 10}, {2, 9}};

// A small cloth, distorted and moving, for the force tests: positions, velocities and
// springs (structural, shear, bending) built here, rest lengths of the undistorted grid.
struct MovingCloth {
    int nx = 4, ny = 3;
    Matrix3X x, v;
    std::vector<Spring> springs;
    explicit MovingCloth(double kd = 0.7) {
        const Matrix3X x0 = gridPositions(nx, ny, 1.5, 1.0);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(-0.1, 0.1);
        x = x0.unaryExpr([&](double a) { return a + u(rng); });
        v = Matrix3X::Zero(3, nx * ny).unaryExpr([&](double) { return 10.0 * u(rng); });
        auto add = [&](int i, int j, double k, SpringType t) {
            springs.push_back({i, j, k, (x0.col(j) - x0.col(i)).norm(), kd, t});
        };
        for (int r = 0; r < ny; ++r)
            for (int c = 0; c < nx; ++c) {
                const int i = gridIndex(c, r, nx);
                if (c + 1 < nx) add(i, gridIndex(c + 1, r, nx), 300.0, SpringType::Structural);
                if (r + 1 < ny) add(i, gridIndex(c, r + 1, nx), 300.0, SpringType::Structural);
                if (c + 1 < nx && r + 1 < ny) add(i, gridIndex(c + 1, r + 1, nx), 120.0, SpringType::Shear);
                if (c + 1 < nx && r + 1 < ny) add(gridIndex(c + 1, r, nx), gridIndex(c, r + 1, nx), 120.0, SpringType::Shear);
                if (c + 2 < nx) add(i, gridIndex(c + 2, r, nx), 20.0, SpringType::Bending);
            }
    }
};

}  // namespace

// ================================ Task 2.1: the springs of the grid ==========================

TEST(Task2_1_ClothSprings, StructuralCountMatchesFormula) {
    for (auto [nx, ny] : kSizes) {
        const auto s = makeClothSprings(gridPositions(nx, ny, 1.0, 1.0), nx, ny, only(true, false, false));
        if (const std::string p = typeProblem(s); !p.empty()) FAIL() << nx << " x " << ny << " grid: " << p;
        EXPECT_EQ(countType(s, SpringType::Structural), structuralCount(nx, ny))
            << nx << " x " << ny << " grid: want (nx-1) ny + nx (ny-1) = " << structuralCount(nx, ny)
            << " structural springs (Strukturfedern, to the right and downward neighbour)";
        EXPECT_EQ(static_cast<int>(s.size()), structuralCount(nx, ny))
            << "the number of springs on a " << nx << " x " << ny << " grid with only structural springs enabled: "
               "nothing but the " << structuralCount(nx, ny) << " structural ones may be built";
    }
}

TEST(Task2_1_ClothSprings, ShearCountMatchesFormula) {
    for (auto [nx, ny] : kSizes) {
        const auto s = makeClothSprings(gridPositions(nx, ny, 1.0, 1.0), nx, ny, only(false, true, false));
        if (const std::string p = typeProblem(s); !p.empty()) FAIL() << nx << " x " << ny << " grid: " << p;
        EXPECT_EQ(countType(s, SpringType::Shear), shearCount(nx, ny))
            << nx << " x " << ny << " grid: want 2 (nx-1)(ny-1) = " << shearCount(nx, ny)
            << " shear springs (Scherfedern: BOTH diagonals of every cell)";
        EXPECT_EQ(static_cast<int>(s.size()), shearCount(nx, ny))
            << "the number of springs on a " << nx << " x " << ny << " grid with only shear springs enabled: nothing but the "
            << shearCount(nx, ny) << " shear ones may be built";
    }
}

TEST(Task2_1_ClothSprings, BendingCountMatchesFormula) {
    for (auto [nx, ny] : kSizes) {
        const auto s = makeClothSprings(gridPositions(nx, ny, 1.0, 1.0), nx, ny, only(false, false, true));
        if (const std::string p = typeProblem(s); !p.empty()) FAIL() << nx << " x " << ny << " grid: " << p;
        EXPECT_EQ(countType(s, SpringType::Bending), bendingCount(nx, ny))
            << nx << " x " << ny << " grid: want (nx-2) ny + nx (ny-2) = " << bendingCount(nx, ny)
            << " bending springs (Biegefedern, to the neighbours TWO apart, right and down; none where the grid is too small)";
        EXPECT_EQ(static_cast<int>(s.size()), bendingCount(nx, ny))
            << "the number of springs on a " << nx << " x " << ny << " grid with only bending springs enabled: nothing but the "
            << bendingCount(nx, ny) << " bending ones may be built";
    }
}

TEST(Task2_1_ClothSprings, OnlyEnabledTypesAreBuilt) {
    const Matrix3X x = gridPositions(5, 4, 1.0, 1.0);
    EXPECT_TRUE(makeClothSprings(x, 5, 4, only(false, false, false)).empty())
        << "the springs of a 5 x 4 grid with every spring type disabled: there must be none; got "
        << makeClothSprings(x, 5, 4, only(false, false, false)).size();
    const auto all = makeClothSprings(x, 5, 4, only(true, true, true));
    if (const std::string p = typeProblem(all); !p.empty()) FAIL() << p;
    EXPECT_EQ(countType(all, SpringType::Structural), structuralCount(5, 4))
        << "the number of structural springs on a 5 x 4 grid with every type enabled: enabling the others must not change it";
    EXPECT_EQ(countType(all, SpringType::Shear), shearCount(5, 4))
        << "the number of shear springs on a 5 x 4 grid with every type enabled: enabling the others must not change it";
    EXPECT_EQ(countType(all, SpringType::Bending), bendingCount(5, 4))
        << "the number of bending springs on a 5 x 4 grid with every type enabled: enabling the others must not change it";
    const auto no_shear = makeClothSprings(x, 5, 4, only(true, false, true));
    EXPECT_EQ(countType(no_shear, SpringType::Shear), 0)
        << "the number of shear springs on a 5 x 4 grid with shear disabled (types.shear.enabled == false): there must be none";
    EXPECT_EQ(static_cast<int>(no_shear.size()), structuralCount(5, 4) + bendingCount(5, 4))
        << "the number of springs on a 5 x 4 grid with structural and bending enabled, shear disabled: exactly the "
           "structural plus the bending ones";
}

TEST(Task2_1_ClothSprings, ConnectsTheRightNeighbours) {
    const int nx = 6, ny = 5;
    const auto s = makeClothSprings(gridPositions(nx, ny, 1.0, 1.0), nx, ny, only(true, true, true));
    ASSERT_FALSE(s.empty()) << "makeClothSprings on a " << nx << " x " << ny << " grid with every spring type enabled must return "
                               "springs; it returned none";
    for (const Spring& sp : s) {
        ASSERT_TRUE(sp.i >= 0 && sp.j >= 0 && sp.i < nx * ny && sp.j < nx * ny)
            << "spring (" << sp.i << ", " << sp.j << ") has an index outside 0.." << nx * ny - 1;
        const int dc = std::abs(sp.i % nx - sp.j % nx), dr = std::abs(sp.i / nx - sp.j / nx);
        const std::string where = "spring between particle " + std::to_string(sp.i) + " (c " + std::to_string(sp.i % nx) + ", r " +
                                  std::to_string(sp.i / nx) + ") and " + std::to_string(sp.j) + " (c " + std::to_string(sp.j % nx) +
                                  ", r " + std::to_string(sp.j / nx) + ") on a " + std::to_string(nx) + " x " + std::to_string(ny) + " grid";
        if (sp.type == SpringType::Structural)
            EXPECT_EQ(dc + dr, 1) << where << ": a structural spring joins direct neighbours (one column or one row apart)";
        else if (sp.type == SpringType::Shear)
            EXPECT_TRUE(dc == 1 && dr == 1) << where << ": a shear spring joins diagonal neighbours";
        else if (sp.type == SpringType::Bending)
            EXPECT_TRUE((dc == 2 && dr == 0) || (dc == 0 && dr == 2)) << where << ": a bending spring joins particles two apart in a row or column";
        else
            ADD_FAILURE() << where << ": its type must be Structural, Shear or Bending; got the value "
                          << static_cast<int>(sp.type);
    }
}

TEST(Task2_1_ClothSprings, NoDuplicateOrSelfSprings) {
    for (auto [nx, ny] : kSizes) {
        const auto s = makeClothSprings(gridPositions(nx, ny, 1.0, 1.0), nx, ny, only(true, true, true));
        std::set<std::pair<int, int>> seen;
        for (const Spring& sp : s) {
            EXPECT_NE(sp.i, sp.j) << "the end points of a spring on a " << nx << " x " << ny
                                  << " grid: a spring joins two different particles; got one from particle " << sp.i << " to itself";
            EXPECT_TRUE(seen.insert({std::min(sp.i, sp.j), std::max(sp.i, sp.j)}).second)
                << nx << " x " << ny << ": particles " << sp.i << " and " << sp.j << " are joined twice (each pair at most once)";
        }
    }
}

TEST(Task2_1_ClothSprings, RestLengthsFromInitialPositions) {
    // A rectangular grid: dx = 3/3 = 1 m, dy = 1/2 = 0.5 m.
    const int nx = 4, ny = 3;
    const auto s = makeClothSprings(gridPositions(nx, ny, 3.0, 1.0), nx, ny, only(true, true, true));
    ASSERT_FALSE(s.empty()) << "makeClothSprings on a " << nx << " x " << ny << " grid (3 m x 1 m) with every spring type enabled "
                               "must return springs; it returned none";
    if (const std::string p = typeProblem(s); !p.empty()) FAIL() << p;
    for (const Spring& sp : s) {
        const bool horizontal = sp.i / nx == sp.j / nx, vertical = sp.i % nx == sp.j % nx;
        double want = 0.0;
        if (sp.type == SpringType::Structural) want = horizontal ? 1.0 : 0.5;
        if (sp.type == SpringType::Shear) want = std::sqrt(1.0 + 0.25);
        if (sp.type == SpringType::Bending) want = horizontal ? 2.0 : (vertical ? 1.0 : -1.0);
        EXPECT_CLOSE(sp.l0, want, 1e-12) << "the rest length (Ruhelänge) of spring " << sp.i << "-" << sp.j
                                        << " on a grid with dx = 1 m, dy = 0.5 m: a spring is relaxed in the initial "
                                           "positions, so it must be their distance, " << want << " m";
    }
    // A distorted grid: l0 is the distance of the given positions, not a grid constant.
    Matrix3X x = gridPositions(nx, ny, 3.0, 1.0);
    for (int i = 0; i < nx * ny; ++i) x.col(i) += Vec3(0.05 * i, 0.02 * (i % 3), -0.03 * i * i / 10.0);
    for (const Spring& sp : makeClothSprings(x, nx, ny, only(true, true, true)))
        EXPECT_CLOSE(sp.l0, (x.col(sp.j) - x.col(sp.i)).norm(), 1e-12)
            << "the rest length l0 of spring " << sp.i << "-" << sp.j << " for positions not on a regular grid: a spring is "
               "relaxed in the given positions, so l0 must be the distance of its particles there";
}

TEST(Task2_1_ClothSprings, StiffnessAndDampingPerType) {
    const auto s = makeClothSprings(gridPositions(5, 5, 1.0, 1.0), 5, 5, only(true, true, true));
    ASSERT_FALSE(s.empty()) << "makeClothSprings on a 5 x 5 grid with every spring type enabled must return springs; it returned none";
    if (const std::string p = typeProblem(s); !p.empty()) FAIL() << p;
    for (const Spring& sp : s) {
        const double k = sp.type == SpringType::Structural ? 100.0 : sp.type == SpringType::Shear ? 50.0 : 10.0;
        const double kd = sp.type == SpringType::Structural ? 0.1 : sp.type == SpringType::Shear ? 0.2 : 0.3;
        EXPECT_EXACT(sp.k, k) << "the stiffness k of spring " << sp.i << "-" << sp.j << ": each type takes k from its own group "
                              << "(structural 100, shear 50, bending 10 N/m here)";
        EXPECT_EXACT(sp.kd, kd) << "the damping kd of spring " << sp.i << "-" << sp.j
                                << ": each type takes kd from its own group (structural 0.1, shear 0.2, bending 0.3 N s/m here)";
    }
}

// ================================ Task 2.2: spring forces =====================================

TEST(Task2_2_SpringForces, OneSpringMatchesHookeAndDamping) {
    Matrix3X x = Matrix3X::Zero(3, 2), v = Matrix3X::Zero(3, 2), f = Matrix3X::Zero(3, 2);
    x.col(1) = Vec3(0, 0, 2);  // particle 1 at (0, 0, 2): stretched by 1
    v.col(0) = Vec3(0, 0, 1);  // particle 0 moves with (0, 0, 1) towards particle 1
    addClothSpringForces({{0, 1, 10.0, 1.0, 2.0, SpringType::Structural}}, x, v, f);
    // Hooke: -10 * 1 along +z on particle 1; damping: relative velocity -1 along +z -> +2.
    EXPECT_TRUE(f.col(1).isApprox(Vec3(0, 0, -8), 1e-12))
        << "the force on particle 1 (x_j) of one spring stretched by 1 m (k = 10) while particle 0 approaches at 1 m/s (kd = 2): "
           "the spring pulls it back with (0, 0, -10), the damper resists the closing with (0, 0, 2), so it must be (0, 0, -8); got "
        << str(f.col(1));
    EXPECT_TRUE(f.col(0).isApprox(Vec3(0, 0, 8), 1e-12))
        << "the force on particle 0 (x_i) of the same spring: actio = reactio, so it must be the opposite, (0, 0, 8); got "
        << str(f.col(0));
}

TEST(Task2_2_SpringForces, InternalForcesSumToZero) {
    MovingCloth cloth;
    Matrix3X f = Matrix3X::Zero(3, cloth.x.cols());
    addClothSpringForces(cloth.springs, cloth.x, cloth.v, f);
    const Vec3 total = f.rowwise().sum();
    EXPECT_LESS(total.norm(), 1e-9 * f.norm())
        << "the net spring force on a distorted, moving cloth: spring forces are internal (actio = reactio for every spring), so "
           "they must sum to zero and create no momentum; got " << str(total);
    EXPECT_GREATER(f.norm(), 1.0) << "the size |f| of all spring forces on a distorted, moving cloth: its springs are stretched and "
                                     "compressed, so the forces must not vanish";
    // Angular momentum: Σ x_i × f_i = 0 for central forces.
    Vec3 torque = Vec3::Zero();
    for (int i = 0; i < cloth.x.cols(); ++i) torque += Vec3(cloth.x.col(i)).cross(Vec3(f.col(i)));
    EXPECT_LESS(torque.norm(), 1e-9 * f.norm())
        << "the net torque of the spring forces on a distorted, moving cloth: spring forces act along the springs, so their "
           "torques must cancel; got " << str(torque);
}

TEST(Task2_2_SpringForces, AddsToExistingForces) {
    MovingCloth cloth;
    Matrix3X f0 = Matrix3X::Constant(3, cloth.x.cols(), 0.25), f = Matrix3X::Zero(3, cloth.x.cols());
    addClothSpringForces(cloth.springs, cloth.x, cloth.v, f);
    addClothSpringForces(cloth.springs, cloth.x, cloth.v, f0);
    const double existingForceChange = (f0 - f - Matrix3X::Constant(3, cloth.x.cols(), 0.25)).norm();
    EXPECT_LESS(existingForceChange, 1e-9 * f.norm())
        << "how much of the 0.25 N per component that f already held was changed or lost: the spring forces come on top of the "
           "other force terms already in f, which must survive the call";
}

TEST(Task2_2_SpringForces, IsMinusGradientOfSpringEnergy) {
    MovingCloth cloth(/*kd=*/0.0);
    const Matrix3X v = Matrix3X::Zero(3, cloth.x.cols());
    Matrix3X f = Matrix3X::Zero(3, cloth.x.cols());
    addClothSpringForces(cloth.springs, cloth.x, v, f);
    const double h = 1e-6;
    for (int i = 0; i < cloth.x.cols(); ++i)
        for (int d = 0; d < 3; ++d) {
            Matrix3X xp = cloth.x, xm = cloth.x;
            xp(d, i) += h, xm(d, i) -= h;
            const double grad = (springEnergy(cloth.springs, xp) - springEnergy(cloth.springs, xm)) / (2 * h);
            EXPECT_CLOSE(f(d, i), -grad, 1e-5 * std::max(1.0, std::abs(grad)))
                << "particle " << i << ", component " << d << ": the spring force must be -dE/dx of E = sum 1/2 k (|x_j-x_i| - l0)^2 "
                << "(finite differences give " << -grad << " N)";
        }
}

TEST(Task2_2_SpringForces, CoincidentParticlesGiveNoNaN) {
    Matrix3X x = Matrix3X::Zero(3, 3), v = Matrix3X::Zero(3, 3), f = Matrix3X::Zero(3, 3);
    x.col(2) = Vec3(0, -1, 0);
    v.col(1) = Vec3(1, 0, 0);
    addClothSpringForces({{0, 1, 100.0, 0.5, 1.0, SpringType::Structural}, {1, 2, 100.0, 0.5, 1.0, SpringType::Structural}}, x, v, f);
    EXPECT_TRUE(f.allFinite()) << "the forces when particles 0 and 1 coincide: their spring has no direction, the force must be "
                                  "finite (zero), not NaN; got " << str(f);
    EXPECT_CLOSE(f(1, 2), 50.0, 1e-9) << "the y force on particle 2, in N: the other spring (1-2, stretched by 0.5, k = 100) must "
                                         "still pull particle 2 up with 50 N";
}

TEST(Task2_2_HangingChain, StaticStretchMatchesAnalytic) {
    // A vertical chain of n particles (column of a 1-wide cloth), the top one pinned, relaxed with
    // damping. At rest link i (from particle i-1 to i) carries the weight of the n - i particles below it:
    // k (l_i - l0) = (n - i) m g.
    const int n = 8;
    const double m = 0.05, k = 400.0, l0 = 0.1, g = 9.81;
    Matrix3X x(3, n), v = Matrix3X::Zero(3, n);
    VectorX w = VectorX::Constant(n, 1.0 / m);
    w[0] = 0.0;
    std::vector<Spring> springs;
    for (int i = 0; i < n; ++i) x.col(i) = Vec3(0, -l0 * i, 0);
    for (int i = 1; i < n; ++i) springs.push_back({i - 1, i, k, l0, 0.0, SpringType::Structural});
    Matrix3X f(3, n);
    for (int s = 0; s < 20000; ++s) {  // symplectic Euler, written here (graded in stage 01)
        f.setZero();
        addClothSpringForces(springs, x, v, f);
        for (int i = 1; i < n; ++i) f.col(i) += Vec3(0, -m * g, 0) - 0.3 * v.col(i);  // gravity and damping, written here
        v += 1e-3 * (f * w.asDiagonal());
        x += 1e-3 * v;
    }
    for (int i = 1; i < n; ++i) {
        const double want = l0 + (n - i) * m * g / k;
        const double linkLength = (x.col(i) - x.col(i - 1)).norm();
        EXPECT_CLOSE(linkLength, want, 1e-6)
            << "the length of link " << i << " of the hanging chain at rest, in m" << ": at rest it carries the weight of the " << n - i << " particles below, so its length must be "
            << "l0 + (n - i) m g / k = " << want << " m";
    }
}

// ================================ Task 2.3: gravity and damping ===============================

TEST(Task2_3_ExternalForces, GravitySumsToTotalMass) {
    ClothSpec spec;
    spec.nx = 6, spec.ny = 4, spec.mass = 0.3;
    const State s = makeGridState(spec);  // m_i = 0.3 / 24 kg, nothing pinned
    Matrix3X f = Matrix3X::Zero(3, s.size());
    addClothExternalForces(s.w, s.v, Vec3(0, -9.81, 0), 0.0, f);
    const Vec3 total = f.rowwise().sum();
    EXPECT_TRUE(total.isApprox(Vec3(0, -0.3 * 9.81, 0), 1e-12))
        << "the total gravity force on a cloth of total mass m_gesamt = 0.3 kg: the weights of its particles must add up to "
           "m_gesamt g = (0, -2.943, 0); got " << str(total);
    EXPECT_CLOSE(f(1, 5), -0.3 / 24 * 9.81, 1e-12) << "the y force on particle 5, in N: each of the 24 particles has the mass "
                                                      "m_gesamt / (nx ny) = 0.0125 kg, so its weight is 0.0125 kg * g";
}

TEST(Task2_3_ExternalForces, PinnedParticlesGetNoForce) {
    VectorX w(3);
    w << 0.0, 2.0, 0.0;
    Matrix3X v = Matrix3X::Ones(3, 3), f = Matrix3X::Zero(3, 3);
    addClothExternalForces(w, v, Vec3(0, -10, 0), 0.5, f);
    EXPECT_TRUE(f.allFinite()) << "the external forces with pinned particles (w = 0, infinite mass) among them: they must be "
                                  "finite, not Inf or NaN; got " << str(f);
    EXPECT_TRUE(f.col(0).isZero() && f.col(2).isZero()) << "the external forces on the pinned particles 0 and 2 (w = 0): a pinned "
                                                           "particle gets no gravity and no damping; got "
                                                        << str(f.col(0)) << " and " << str(f.col(2));
    EXPECT_TRUE(f.col(1).isApprox(Vec3(-0.5, -5.5, -0.5), 1e-12))
        << "the external force on particle 1 (w = 2 1/kg, v = (1, 1, 1), g = (0, -10, 0), c = 0.5): its weight plus the air "
           "damping against its velocity must be (-0.5, -5.5, -0.5); got " << str(f.col(1));
}

TEST(Task2_3_ExternalForces, DampingOpposesVelocity) {
    VectorX w = VectorX::Constant(2, 1.0);
    Matrix3X v(3, 2), f = Matrix3X::Zero(3, 2);
    v << 1, -4, 2, 0, 0, 3;
    addClothExternalForces(w, v, Vec3::Zero(), 2.0, f);
    EXPECT_TRUE(f.isApprox(-2.0 * v, 1e-12)) << "the external forces without gravity (c = 2): air damping must oppose each "
                                                "particle's velocity " << str(v) << ", in proportion to it, expected "
                                             << str(-2.0 * v) << "; got " << str(f);
}

TEST(Task2_3_ExternalForces, AddsToExistingForces) {
    VectorX w = VectorX::Constant(2, 0.5);
    Matrix3X v = Matrix3X::Zero(3, 2), f = Matrix3X::Constant(3, 2, 1.0);
    addClothExternalForces(w, v, Vec3(0, -1, 0), 0.0, f);
    EXPECT_TRUE(f.col(0).isApprox(Vec3(1, -1, 1), 1e-12))
        << "the force on particle 0 (2 kg, g = (0, -1, 0)) when f already held (1, 1, 1) from other terms: the weight comes on top "
           "of them, so it must be (1, -1, 1); got " << str(f.col(0));
}

// ============================ Randomised property tests =======================================
// Random orientations, scales from 1 mm to 100 m, random stiffnesses, damping and masses; seeds
// 1..kPropertySeeds (test_util.h). Expected behaviour from physics, never from the reference.

namespace {
using testing_util::forEachSeed;
using testing_util::RandomGeometry;

// A 4 x 3 cloth of a random size (scale 1 mm to 100 m), randomly rotated and moved, its particles
// displaced by up to 20 % of the spacing, moving with random velocities; structural, shear and bending
// springs built here with random k, kd and the rest lengths of the undisplaced, unrotated grid.
struct RandomCloth {
    int nx = 4, ny = 3;
    double s = 1.0;
    Matrix3X x, v;
    std::vector<Spring> springs;
    RandomCloth(unsigned seed, bool damping) {
        RandomGeometry G(seed);
        s = G.scale();
        const Eigen::Matrix3d R = G.rotation();
        const Matrix3X x0 = s * gridPositions(nx, ny, 1.5, 1.0);
        const Vec3 t = G.point(5.0 * s);
        x.resize(3, nx * ny), v.resize(3, nx * ny);
        for (int i = 0; i < nx * ny; ++i) {
            x.col(i) = R * (x0.col(i) + G.point(0.1 * s)) + t;
            v.col(i) = G.point(s);
        }
        auto add = [&](int i, int j, SpringType type) {
            springs.push_back({i, j, G.logUniform(1.0, 1e3), (x0.col(j) - x0.col(i)).norm(),
                               damping ? G.logUniform(0.1, 10.0) : 0.0, type});
        };
        for (int r = 0; r < ny; ++r)
            for (int c = 0; c < nx; ++c) {
                const int i = gridIndex(c, r, nx);
                if (c + 1 < nx) add(i, gridIndex(c + 1, r, nx), SpringType::Structural);
                if (r + 1 < ny) add(i, gridIndex(c, r + 1, nx), SpringType::Structural);
                if (c + 1 < nx && r + 1 < ny) add(i, gridIndex(c + 1, r + 1, nx), SpringType::Shear);
                if (c + 1 < nx && r + 1 < ny) add(gridIndex(c + 1, r, nx), gridIndex(c, r + 1, nx), SpringType::Shear);
                if (c + 2 < nx) add(i, gridIndex(c + 2, r, nx), SpringType::Bending);
                if (r + 2 < ny) add(i, gridIndex(c, r + 2, nx), SpringType::Bending);
            }
    }
};
}  // namespace

TEST(Task2_2_SpringForces, RandomOrientationsScalesAndStiffnesses) {
    // Without damping the spring forces are minus the gradient of the spring energy (finite differences),
    // for a cloth of any size and orientation, and as internal central forces they have no net force and
    // no net torque.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        const RandomCloth cloth(seed, false);
        const Matrix3X v = Matrix3X::Zero(3, cloth.x.cols());
        Matrix3X f = Matrix3X::Zero(3, cloth.x.cols());
        addClothSpringForces(cloth.springs, cloth.x, v, f);
        const double h = 1e-6 * cloth.s, fscale = 1e3 * cloth.s;  // k up to 1e3 N/m, stretches ~ s
        for (int i = 0; i < cloth.x.cols(); ++i)
            for (int d = 0; d < 3; ++d) {
                Matrix3X xp = cloth.x, xm = cloth.x;
                xp(d, i) += h, xm(d, i) -= h;
                const double grad = (springEnergy(cloth.springs, xp) - springEnergy(cloth.springs, xm)) / (2 * h);
                if (!std::isfinite(f(d, i)) || std::abs(f(d, i) + grad) > 1e-5 * fscale)
                    return testing::AssertionFailure()
                           << "The spring forces must be minus the gradient of the spring energy E = sum 1/2 k (|x_j-x_i| - l0)^2 "
                              "for a cloth of any size and orientation: particle " << i << ", component " << d
                           << ": finite differences give " << -grad << " N, your force is " << f(d, i)
                           << " N (cloth scale " << cloth.s << " m, particle at " << str(cloth.x.col(i)) << ").";
            }
        Vec3 total = Vec3::Zero(), torque = Vec3::Zero();
        for (int i = 0; i < cloth.x.cols(); ++i) total += f.col(i), torque += Vec3(cloth.x.col(i)).cross(Vec3(f.col(i)));
        if (total.norm() > 1e-9 * fscale || torque.norm() > 1e-9 * fscale * (cloth.x.norm() + cloth.s))
            return testing::AssertionFailure() << "Spring forces are internal and central: they must sum to zero and have no net "
                                                  "torque; got the net force " << str(total) << " N and the net torque "
                                               << str(torque) << " N m (cloth scale " << cloth.s << " m).";
        return testing::AssertionSuccess();
    });
}

TEST(Task2_2_SpringForces, EverySpringDissipatesPowerWithRandomDamping) {
    // With k = 0 only the dampers act: each spring (structural, shear or bending) removes the power
    // kd ((v_j - v_i).d)^2 from the cloth, so the total power sum f_i.v_i is minus the sum of these.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomCloth cloth(seed, true);
        for (Spring& sp : cloth.springs) sp.k = 0.0;
        Matrix3X f = Matrix3X::Zero(3, cloth.x.cols());
        addClothSpringForces(cloth.springs, cloth.x, cloth.v, f);
        double power = 0.0, want = 0.0, scale = 0.0;
        for (int i = 0; i < cloth.x.cols(); ++i) power += f.col(i).dot(cloth.v.col(i));
        for (const Spring& sp : cloth.springs) {
            const Vec3 dir = (cloth.x.col(sp.j) - cloth.x.col(sp.i)).normalized();
            const Vec3 dv = cloth.v.col(sp.j) - cloth.v.col(sp.i);
            want -= sp.kd * dv.dot(dir) * dv.dot(dir);
            scale += sp.kd * dv.squaredNorm();
        }
        if (!std::isfinite(power) || std::abs(power - want) > 1e-9 * scale)
            return testing::AssertionFailure()
                   << "Every spring's damper (structural, shear and bending alike, each with its own kd) must dissipate the "
                      "power kd ((v_j - v_i).d)^2: the damping forces of this cloth must do the work " << want
                   << " W per second, yours do " << power << " W (cloth scale " << cloth.s << " m, "
                   << cloth.springs.size() << " springs).";
        return testing::AssertionSuccess();
    });
}

TEST(Task2_3_ExternalForces, GravityInAnyDirectionWithRandomMasses) {
    // Equivalence principle: without air damping every free particle, whatever its mass, is accelerated
    // by exactly g (a_i = w_i f_i), for g pointing in any direction; air damping -c v rotates with v.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const int n = 6;
        const Vec3 g = G.logUniform(0.1, 100.0) * G.unitVector();
        VectorX w(n);
        Matrix3X v(3, n);
        for (int i = 0; i < n; ++i) w[i] = 1.0 / G.logUniform(1e-4, 1e2), v.col(i) = G.point(10.0);
        w[2] = 0.0;  // pinned
        Matrix3X f = Matrix3X::Zero(3, n);
        addClothExternalForces(w, v, g, 0.0, f);
        for (int i = 0; i < n; ++i) {
            const Vec3 a = w[i] > 0 ? Vec3(w[i] * f.col(i)) : Vec3(f.col(i));
            const Vec3 want = w[i] > 0 ? g : Vec3::Zero();
            if (!a.allFinite() || (a - want).norm() > 1e-12 * g.norm())
                return testing::AssertionFailure()
                       << "Gravity must accelerate every free particle by exactly g, in the direction of g (here " << str(g)
                       << " m/s^2, not along a fixed axis), whatever its mass, and must not act on pinned ones: particle " << i
                       << " with w = " << w[i] << " 1/kg gets the force " << str(f.col(i)) << " N, i.e. the acceleration w f = "
                       << str(a) << " m/s^2.";
        }
        const double c = G.logUniform(0.01, 10.0);
        const Eigen::Matrix3d R = G.rotation();
        Matrix3X f1 = Matrix3X::Zero(3, n), f2 = Matrix3X::Zero(3, n);
        addClothExternalForces(w, v, g, c, f1);
        addClothExternalForces(w, R * v, R * g, c, f2);
        if ((f2 - R * f1).norm() > 1e-12 * (R * f1).norm())
            return testing::AssertionFailure()
                   << "Rotating gravity and the velocities must rotate the forces m g - c v (no preferred axis): g = " << str(g)
                   << " m/s^2, c = " << c << " N s/m; particle 0: got " << str(f2.col(0)) << " N after rotating, expected "
                   << str(R * f1.col(0)) << " N.";
        return testing::AssertionSuccess();
    });
}

// ================================ Experiment (answers.json) ===================================
// The stage's experiment (task sheet, "Experiment"): predict from theory, measure with your own code,
// explain the difference, in exercises/02_mfn/answers.json. This test checks only that the file is
// complete and well formed; the numbers are graded by the instructor.
TEST(Experiments, AnswerFileIsComplete) {
    EXPECT_TRUE(testing_util::answerFileIsComplete("02_mfn", {"critical_dt"}, {"critical_dt"}));
}
