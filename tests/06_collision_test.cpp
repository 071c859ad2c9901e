// Graded tests of stage 06 — collision constraints and velocityUpdate.
// Test names start with the task they check (Task6_4 = exercise 6.4). Points: 06_collision.points.json.
// The whole-step tests run a small PBD loop written here (not your stage 03) with your collision code,
// and compare with analytic solutions: incline with Coulomb friction, rebound height with restitution.
#include <cmath>
#include <functional>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

#include "clothlab/exercise/06_collision.h"
#include "clothlab/sim/sweeps.h"
#include "test_util.h"

using namespace clothlab;

namespace {

constexpr double kPi = 3.14159265358979323846;
const Vec3 kG(0.0, -9.81, 0.0);

using testing_util::str;

PlaneCollider plane(const Vec3& point, const Vec3& normal, double mu = 0.0, double e = 0.0) {
    PlaneCollider c;
    c.point = point;
    c.normal = normal.normalized();
    c.friction = mu;
    c.restitution = e;
    return c;
}
SphereCollider sphere(const Vec3& centre, double radius, double mu = 0.0, double e = 0.0) {
    SphereCollider c;
    c.center = centre;
    c.radius = radius;
    c.friction = mu;
    c.restitution = e;
    return c;
}
// A plane or a sphere, for the scenes of several colliders.
struct AnyCollider {
    AnyCollider(const PlaneCollider& c) : isPlane(true), plane(c) {}    // NOLINT: implicit on purpose
    AnyCollider(const SphereCollider& c) : isPlane(false), sphere(c) {}  // NOLINT: implicit on purpose
    bool isPlane;
    PlaneCollider plane;
    SphereCollider sphere;
};

// Particles with gravity, colliders and optional extra constraints, stepped by lines (5)-(16).
struct Particles {
    Matrix3X x, v;
    VectorX w;
};
using Extra = std::function<void(Matrix3X& p, const VectorX& w)>;
void step(Particles& P, const std::vector<AnyCollider>& colliders, double h, double dt, int iterations,
          const Extra& extra = {}) {
    for (int i = 0; i < P.x.cols(); ++i)
        if (P.w[i] > 0) P.v.col(i) += dt * kG;
    Matrix3X p = P.x + dt * P.v;
    std::vector<CollisionConstraint> contacts;
    for (int i = 0; i < P.x.cols(); ++i)
        for (const AnyCollider& c : colliders) {
            CollisionConstraint cc;
            const bool hit = c.isPlane ? generatePlaneConstraint(i, P.x.col(i), p.col(i), c.plane, h, dt, &cc)
                                       : generateSphereConstraint(i, P.x.col(i), p.col(i), c.sphere, h, dt, &cc);
            if (hit) contacts.push_back(cc);
        }
    for (int it = 0; it < iterations; ++it) {
        if (extra) extra(p, P.w);
        // p_i += projectCollisionConstraint(p_i, w_i, h, c) for every contact c, in order: the solver's
        // own loop (sim/sweeps.h), which the grader runs in your code's process as one call.
        projectCollisionSweep(contacts, P.w, h, p);
    }
    P.v = (p - P.x) / dt;
    P.x = p;
    velocityUpdate(P.v, contacts);
}

// Signed distance of a point to the collider surface (outside positive).
double distanceTo(const AnyCollider& c, const Vec3& x) {
    if (c.isPlane) return (x - c.plane.point).dot(c.plane.normal);
    return (x - c.sphere.center).norm() - c.sphere.radius;
}

}  // namespace

// ---- Task 6.1 ------------------------------------------------------------------------------------
TEST(Task6_1_PlaneConstraint, GeneratedOnlyWithinTheThickness) {
    const PlaneCollider c = plane(Vec3(0, 1, 0), Vec3(0, 1, 0), 0.3, 0.2);
    CollisionConstraint cc;
    EXPECT_FALSE(generatePlaneConstraint(3, Vec3(0, 2, 0), Vec3(0, 1.5, 0), c, 0.1, 0.01, &cc))
        << "whether a constraint is generated for a particle ending 0.5 m above the plane (thickness 0.1 m): it is clear of "
           "the plane and its thickness, so there must be none";
    EXPECT_TRUE(generatePlaneConstraint(3, Vec3(0, 2, 0), Vec3(0.1, 1.05, 0), c, 0.1, 0.01, &cc))
        << "whether a constraint is generated for a particle ending 0.05 m above the plane, closer than the thickness 0.1 m: "
           "there must be one";
    EXPECT_EQ(cc.i, 3) << "the particle index of the constraint: it must be the index passed in";
    EXPECT_LESS((cc.n - Vec3(0, 1, 0)).norm(), 1e-12) << "the constraint normal n_s: it must be the plane's normal (0, 1, 0); got "
                                                      << str(cc.n);
    EXPECT_CLOSE((cc.q - Vec3(0, 1, 0)).dot(cc.n), 0.0, 1e-12) << "the height of the contact point q_s = " << str(cc.q) << " above the plane, in m: it must lie on the plane";
    EXPECT_LESS((cc.start - Vec3(0, 2, 0)).norm(), 1e-12) << "the constraint's start position: it must be the particle's position "
                                                          "at the start of the step, (0, 2, 0); got " << str(cc.start);
    EXPECT_CLOSE(cc.vnBefore, (1.05 - 2.0) / 0.01, 1e-9) << "vnBefore, in m/s: the normal velocity with which the particle approached the plane over the step "
                                                          "(x = (0, 2, 0) to p = (0.1, 1.05, 0) in dt = 0.01 s)";
    EXPECT_EXACT(cc.friction, 0.3) << "the constraint's friction coefficient: it must be the collider's, 0.3";
    EXPECT_EXACT(cc.restitution, 0.2) << "the constraint's restitution: it must be the collider's, 0.2";
}

TEST(Task6_1_PlaneConstraint, FastParticleBelowThePlaneIsCaught) {
    const PlaneCollider c = plane(Vec3(0, 0, 0), Vec3(0, 0, 1));
    CollisionConstraint cc;
    EXPECT_TRUE(generatePlaneConstraint(0, Vec3(0, 0, 1), Vec3(0, 0, -5), c, 0.01, 0.01, &cc))
        << "whether a constraint is generated for a particle that ends 5 m below the plane: it went through, so there must be one";
}

// ---- Task 6.2 ------------------------------------------------------------------------------------
TEST(Task6_2_SphereConstraint, EntryPointAndNormalAlongThePath) {
    const SphereCollider c = sphere(Vec3(1, 0, 0), 0.5);
    CollisionConstraint cc;
    // Straight down onto the top of the sphere.
    ASSERT_TRUE(generateSphereConstraint(2, Vec3(1, 1, 0), Vec3(1, 0.3, 0), c, 0.0, 0.1, &cc))
        << "whether a constraint is generated for the path (1, 1, 0) -> (1, 0.3, 0): it enters the sphere of radius 0.5 around "
           "(1, 0, 0), so there must be one";
    EXPECT_LESS((cc.n - Vec3(0, 1, 0)).norm(), 1e-9) << "the constraint normal n_s for a path entering the sphere straight from "
                                                     "above: it must be the surface normal there, (0, 1, 0); got " << str(cc.n);
    EXPECT_LESS((cc.q - Vec3(1, 0.5, 0)).norm(), 1e-9) << "the contact point q_s for a path entering straight from above: it must be "
                                                       "the top of the sphere, (1, 0.5, 0); got " << str(cc.q);
    // Oblique entry: the normal at the entry point, not at p.
    const Vec3 x(0.2, 0.8, 0), p(1.0, 0.0, 0);
    ASSERT_TRUE(generateSphereConstraint(2, x, p, c, 0.1, 0.1, &cc))
        << "whether a constraint is generated for the oblique path " << str(x) << " -> " << str(p)
        << " into the sphere (R = 0.5, h = 0.1): it ends at the centre, so there must be one";
    const double Rh = 0.6;
    const Vec3 u = p - x, f = x - c.center;  // solve |f + t u| = Rh here
    const double t = (-u.dot(f) - std::sqrt(u.dot(f) * u.dot(f) - u.squaredNorm() * (f.squaredNorm() - Rh * Rh))) / u.squaredNorm();
    const Vec3 n = (f + t * u).normalized();
    EXPECT_LESS((cc.n - n).norm(), 1e-9) << "the constraint normal n_s for an oblique path: it must be the surface normal where "
                                         "the path enters the inflated sphere (radius R + h), " << str(n) << "; got " << str(cc.n);
    EXPECT_LESS((cc.q - (c.center + 0.5 * n)).norm(), 1e-9) << "the contact point q_s for an oblique path: it must be the point of "
                                                           "the sphere's surface below the entry point, " << str(c.center + 0.5 * n)
                                                        << "; got " << str(cc.q);
}

TEST(Task6_2_SphereConstraint, FastParticleDoesNotTunnel) {
    const SphereCollider c = sphere(Vec3(0, 0, 0), 0.5);
    CollisionConstraint cc;
    // From 1 m above to 1 m below in one step: p is outside the sphere, but the path crossed it.
    ASSERT_TRUE(generateSphereConstraint(0, Vec3(0.1, 1, 0), Vec3(0.1, -1, 0), c, 0.01, 0.01, &cc))
        << "whether a constraint is generated for a path that crosses the whole sphere in one step: "
           "the particle went through the sphere, so there must be one (no tunnelling)";
    EXPECT_GREATER(cc.n.y(), 0.9) << "the y component of the constraint normal for a path crossing the sphere from top to bottom: the normal must be the one where the particle entered (top), got " << str(cc.n);
    EXPECT_FALSE(generateSphereConstraint(0, Vec3(2, 1, 0), Vec3(2, -1, 0), c, 0.01, 0.01, &cc))
        << "whether a constraint is generated for a path that passes beside the sphere: it never touches it, so there must be none";
    EXPECT_FALSE(generateSphereConstraint(0, Vec3(0, 2, 0), Vec3(0, 1, 0), c, 0.01, 0.01, &cc))
        << "whether a constraint is generated for a path that stops before the sphere: it never touches it, so there must be none";
}

TEST(Task6_2_SphereConstraint, StartInsideUsesTheClosestSurfacePoint) {
    const SphereCollider c = sphere(Vec3(0, 0, 0), 1.0);
    CollisionConstraint cc;
    ASSERT_TRUE(generateSphereConstraint(0, Vec3(0.5, 0, 0), Vec3(0, 0.6, 0), c, 0.0, 0.01, &cc))
        << "whether a constraint is generated when x and p are both inside the sphere: the particle is inside, so there must be one";
    EXPECT_LESS((cc.n - Vec3(0, 1, 0)).norm(), 1e-12) << "the constraint normal n_s for a particle already inside (p = (0, 0.6, 0)): "
                                                      "it must point from the centre towards p, (0, 1, 0); got " << str(cc.n);
    EXPECT_LESS((cc.q - Vec3(0, 1, 0)).norm(), 1e-12) << "the contact point q_s for a particle already inside: it must be the "
                                                      "surface point in the direction of the normal, (0, 1, 0); got " << str(cc.q);
    ASSERT_TRUE(generateSphereConstraint(0, Vec3(0.5, 0, 0), Vec3(0, 0, 0), c, 0.0, 0.01, &cc))
        << "whether a constraint is generated for p exactly at the centre: the particle is inside, so there must be one";
    EXPECT_TRUE(cc.n.allFinite() && std::abs(cc.n.norm() - 1.0) < 1e-12) << "the constraint normal n_s for p exactly at the centre: the direction is undefined, but it must still be a unit vector (see the header); got "
                                                                          << str(cc.n);
}

// ---- Task 6.3 ------------------------------------------------------------------------------------
TEST(Task6_3_ProjectCollision, ViolatedConstraintIsSatisfiedExactly) {
    CollisionConstraint cc;
    cc.q = Vec3(0, 0, 0), cc.n = Vec3(0, 1, 0), cc.start = Vec3(0.3, 0.5, 0);
    const Vec3 p(0.4, -0.2, 0.1);
    const Vec3 dp = projectCollisionConstraint(p, 1.0, 0.05, cc);
    const double constraintAfter = (p + dp - cc.q).dot(cc.n) - 0.05;
    EXPECT_CLOSE(constraintAfter, 0.0, 1e-12) << "the collision constraint C after projecting a particle 0.2 m below the surface "
                                                 "(h = 0.05 m), in m: the projection must put it exactly at the thickness h; dp = "
                                              << str(dp);
    const double dpSideways = (dp - dp.dot(cc.n) * cc.n).norm();
    EXPECT_LESS(dpSideways, 1e-12) << "the part of the correction dp = " << str(dp) << " along the surface, in m: without friction "
                                      "a contact can only push along its normal n_s";
}

TEST(Task6_3_ProjectCollision, InequalityOnlyWhenViolatedAndNotForPinned) {
    CollisionConstraint cc;
    cc.q = Vec3(0, 0, 0), cc.n = Vec3(0, 1, 0);
    EXPECT_EXACT(projectCollisionConstraint(Vec3(0, 0.2, 0), 1.0, 0.05, cc).norm(), 0.0)
        << "the length of the correction of a particle 0.2 m above the surface (C > 0), in m: a collision is an inequality "
           "constraint, it must not pull the particle back to the surface";
    EXPECT_EXACT(projectCollisionConstraint(Vec3(0, -0.2, 0), 0.0, 0.05, cc).norm(), 0.0)
        << "the length of the correction of a pinned particle (w = 0) below the surface, in m: a pinned particle never moves";
}

TEST(Task6_3_ProjectCollision, StaticFrictionStopsSmallSlips) {
    CollisionConstraint cc;
    cc.q = Vec3(0, 0, 0), cc.n = Vec3(0, 1, 0), cc.start = Vec3(1, 0.01, 0);
    cc.friction = 0.5;
    const Vec3 p(1.02, -0.05, 0);  // 2 cm sideways, 6 cm too deep (h = 1 cm)
    const Vec3 dp = projectCollisionConstraint(p, 1.0, 0.01, cc);
    EXPECT_CLOSE(p.x() + dp.x(), 1.0, 1e-12) << "the x position after the projection, in m: the particle slid |t| = 0.02 m along the surface, less than the static "
           "friction allows (mu |C| = 0.03 m), so it must stick at x = 1 (no sideways slip)";
    EXPECT_CLOSE(p.y() + dp.y(), 0.01, 1e-12) << "the y position after the projection, in m: the particle must be pushed out to the thickness h = 0.01 m";
    cc.friction = 0.2;
    const Vec3 dp2 = projectCollisionConstraint(p, 1.0, 0.01, cc);
    EXPECT_CLOSE(p.x() + dp2.x(), 1.02, 1e-12) << "the x position after the projection, in m: the sideways move |t| = 0.02 m exceeds what static friction holds "
           "(mu |C| = 0.012 m), so the particle must slide and keep it";
}

// ---- Task 6.4 ------------------------------------------------------------------------------------
TEST(Task6_4_VelocityUpdate, RestitutionReflectsTheIncomingNormalVelocity) {
    Matrix3X v = Matrix3X::Zero(3, 2);
    v.col(1) = Vec3(0, 0.0, 0);  // after the solve: normal velocity removed
    CollisionConstraint cc;
    cc.i = 1, cc.n = Vec3(0, 1, 0), cc.vnBefore = -4.0, cc.restitution = 0.5;
    velocityUpdate(v, {cc});
    EXPECT_CLOSE(v(1, 1), 2.0, 1e-12) << "the outgoing normal velocity of particle 1, in m/s, after a contact with restitution e = 0.5 hit at -4 m/s: "
           "it must rebound with e times the incoming speed";
    EXPECT_EXACT(v.col(0).norm(), 0.0) << "the speed of particle 0, which has no contact, in m/s: a particle without contact keeps "
                                          "its (zero) velocity; its velocity is " << str(v.col(0));
    v.col(1) = Vec3(0, 3.0, 0);  // already separating faster than e |v_in|
    velocityUpdate(v, {cc});
    EXPECT_CLOSE(v(1, 1), 3.0, 1e-12) << "the normal velocity of a particle that already separates at 3 m/s (faster than e times its approach), in m/s: "
           "restitution must not slow it";
}

TEST(Task6_4_VelocityUpdate, CoulombFrictionOnTheTangentialVelocity) {
    Matrix3X v(3, 1);
    v.col(0) = Vec3(1.0, 0.0, 0.0);
    CollisionConstraint cc;
    cc.i = 0, cc.n = Vec3(0, 1, 0), cc.vnBefore = -2.0, cc.friction = 0.25;
    velocityUpdate(v, {cc});
    EXPECT_CLOSE(v(0, 0), 0.5, 1e-12) << "the tangential velocity after the contact, in m/s: with mu = 0.25 and a normal velocity change of 2 m/s, friction "
           "must remove 0.5 m/s of it (Coulomb: the friction impulse is at most mu times the normal one)";
    v.col(0) = Vec3(1.0, 0.0, 0.0);
    cc.friction = 2.0;
    velocityUpdate(v, {cc});
    EXPECT_CLOSE(v(0, 0), 0.0, 1e-12) << "the tangential velocity after a contact with strong friction (mu = 2), in m/s: friction may stop the particle but "
           "never reverse it";
    EXPECT_TRUE(v.allFinite()) << "velocityUpdate with mu = 2 (friction larger than needed to stop) must give finite velocities; got "
                               << str(v.col(0));
    v.col(0) = Vec3(1.0, 0.0, 0.0);
    cc.vnBefore = 0.5;  // was separating: no normal impulse, no friction
    velocityUpdate(v, {cc});
    EXPECT_CLOSE(v(0, 0), 1.0, 1e-12) << "the tangential velocity after a contact without normal velocity change, in m/s: no normal impulse, so no friction "
           "may act and it must stay 1";
}

// ---- Whole steps (all tasks together) ---------------------------------------------------------------
TEST(Task6_4_CollisionSteps, NothingPenetratesIncludingFastParticles) {
    const std::vector<AnyCollider> cols = {plane(Vec3(0, -1, 0), Vec3(0, 1, 0)), sphere(Vec3(0, 0, 0), 0.4)};
    Particles P;
    P.x.resize(3, 5);
    P.x << 0.0, 0.1, -0.2, 0.3, 2.0,  //
        1.0, 2.0, 1.5, 3.0, 0.0,      //
        0.0, 0.1, 0.0, -0.1, 0.0;
    P.v = Matrix3X::Zero(3, 5);
    P.v.col(3) = Vec3(0, -200, 0);  // 2 m per step at dt = 0.01: faster than the sphere is wide
    P.v.col(4) = Vec3(-150, 0, 0);  // sideways through the sphere
    P.w = VectorX::Ones(5);
    const double h = 0.01;
    for (int s = 0; s < 100; ++s) {
        step(P, cols, h, 0.01, 4);
        for (int i = 0; i < 5; ++i)
            for (const auto& c : cols)
                ASSERT_GREATER_EQ(distanceTo(c, P.x.col(i)), -1e-9)
                    << "the signed distance of a particle to a collider's surface, in m (negative: inside), after step " << s << ": particle " << i << " at " << str(P.x.col(i)) << " is inside a collider";
    }
    EXPECT_GREATER(P.x(0, 4), 0.0) << "the x position of the sideways-flying particle 4 at the end, in m: the wall at x = 0 must "
                                      "have stopped it (no tunnelling to x < 0)";
}

TEST(Task6_4_CollisionSteps, ClothRestingOnAPlaneDoesNotJitter) {
    // 4 x 4 particles joined by links, lying on the ground at the thickness h, 10 s of rest.
    const double h = 0.01, dt = 0.01;
    Particles P;
    P.x.resize(3, 16);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) P.x.col(r * 4 + c) = Vec3(0.1 * c, h, 0.1 * r);
    P.v = Matrix3X::Zero(3, 16);
    P.w = VectorX::Constant(16, 16.0);
    const Matrix3X x0 = P.x;
    const Extra links = [](Matrix3X& p, const VectorX& w) {
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) {
                if (c < 3) testing_util::projectRod(p, w, r * 4 + c, r * 4 + c + 1, 0.1);
                if (r < 3) testing_util::projectRod(p, w, r * 4 + c, r * 4 + c + 4, 0.1);
            }
    };
    const std::vector<AnyCollider> cols = {plane(Vec3(0, 0, 0), Vec3(0, 1, 0), 0.5)};
    double maxDev = 0, maxV = 0;
    for (int s = 0; s < 1000; ++s) {
        step(P, cols, h, dt, 10, links);
        maxDev = std::max(maxDev, (P.x - x0).cwiseAbs().maxCoeff());
        maxV = std::max(maxV, P.v.cwiseAbs().maxCoeff());
    }
    EXPECT_LESS(maxDev, 1e-6) << "the largest displacement of a cloth resting on the ground over 10 s, in m: at rest on a "
                                 "surface it must stay put";
    EXPECT_LESS(maxV, 1e-4) << "the largest velocity component of a cloth resting on the ground over 10 s, in m/s: at rest it "
                               "must not jitter";
}

TEST(Task6_4_CollisionSteps, BlockOnAnInclineSticksWhenMuIsAtLeastTanTheta) {
    const double theta = 25.0 * kPi / 180.0, h = 0.01, dt = 0.005;
    const Vec3 n(-std::sin(theta), std::cos(theta), 0);  // slope falls towards +x
    for (double mu : {std::tan(theta) + 0.02, 0.8}) {
        const std::vector<AnyCollider> cols = {plane(Vec3(0, 0, 0), n, mu)};
        Particles P;
        P.x = Matrix3X(3, 1);
        P.x.col(0) = h * n;
        P.v = Matrix3X::Zero(3, 1);
        P.w = VectorX::Ones(1);
        for (int s = 0; s < 400; ++s) step(P, cols, h, dt, 4);
        const double slid = (P.x.col(0) - h * n).norm();
        EXPECT_LESS(slid, 1e-9) << "how far the block on a 25 degree incline slid in 2 s, in m: mu = " << mu << " >= tan(theta) = "
                                << std::tan(theta) << ", so static friction must hold it; it is at " << str(P.x.col(0));
    }
}

TEST(Task6_4_CollisionSteps, BlockOnAnInclineSlidesWithTheAnalyticAcceleration) {
    const double theta = 30.0 * kPi / 180.0, h = 0.01, dt = 0.001, T = 1.0;
    const Vec3 n(-std::sin(theta), std::cos(theta), 0);
    for (double mu : {0.0, 0.2, 0.45}) {
        const std::vector<AnyCollider> cols = {plane(Vec3(0, 0, 0), n, mu)};
        Particles P;
        P.x = Matrix3X(3, 1);
        P.x.col(0) = h * n;
        P.v = Matrix3X::Zero(3, 1);
        P.w = VectorX::Ones(1);
        const int steps = static_cast<int>(std::lround(T / dt));
        for (int s = 0; s < steps; ++s) step(P, cols, h, dt, 4);
        const double a = 9.81 * (std::sin(theta) - mu * std::cos(theta));
        const double speed = P.v.col(0).norm();
        EXPECT_CLOSE(speed, a * T, 0.01 * a * T) << "the speed of the block sliding down a 30 degree incline after " << T << " s with mu = " << mu
                                                << ", in m/s: gravity along the slope minus kinetic friction must give g (sin - mu cos) t = "
                                                << a * T << " m/s";
        const double dist = (P.x.col(0) - h * n).norm();
        EXPECT_CLOSE(dist, 0.5 * a * T * T, 0.015 * 0.5 * a * T * T) << "the distance the block slid down the 30 degree incline in " << T << " s with mu = " << mu << ", in m: uniform acceleration must give a t^2 / 2 = " << 0.5 * a * T * T << " m (1.5 %)";
        const double heightAboveSlope = P.x.col(0).dot(n);
        EXPECT_CLOSE(heightAboveSlope, h, 1e-9) << "the height of the sliding block above the slope, in m: it must stay on the slope "
                                                   "at the thickness h = 0.01 m";
    }
}

TEST(Task6_4_CollisionSteps, RestitutionScalesTheSpeedOfABounce) {
    // A particle dropped onto a plane, stepped through the whole loop: the speed it leaves the plane with
    // (the first upward velocity) is e times the speed it hit it with (the last downward one), to within
    // what gravity adds in the one step of the impact (g dt = 1e-3 m/s of about 4.4 m/s).
    const double H = 1.0, h = 0.01, dt = 1e-4;
    for (double e : {0.3, 0.7}) {
        const std::vector<AnyCollider> cols = {plane(Vec3(0, 0, 0), Vec3(0, 1, 0), 0.0, e)};
        Particles P;
        P.x = Matrix3X(3, 1);
        P.x.col(0) = Vec3(0, h + H, 0);
        P.v = Matrix3X::Zero(3, 1);
        P.w = VectorX::Ones(1);
        double before = 0.0, after = 0.0;  // speeds, m/s
        for (int s = 0; s < 20000 && after == 0.0; ++s) {
            const double vy = P.v(1, 0);
            step(P, cols, h, dt, 2);
            if (vy < 0 && P.v(1, 0) > 0) before = -vy, after = P.v(1, 0);
        }
        EXPECT_GREATER(after, 0.0) << "the upward speed of a particle dropped from H = 1 m onto a plane with restitution e = " << e
                                   << " after it hit the plane, in m/s: with e > 0 it must bounce (its velocity turn upward)";
        EXPECT_CLOSE(after, e * before, 0.01 * e * before)
            << "the speed in m/s with which a particle dropped from H = 1 m leaves a plane with restitution e = " << e
            << ", after hitting it at " << before << " m/s: restitution must send it back with e times the speed it came with";
    }
}

// ============================ Randomised property tests =======================================
// Planes and spheres in any orientation and position, sizes from 1 mm to 100 m, oblique paths that hit
// anywhere (not at a symmetric point), random friction and restitution; seeds 1..kPropertySeeds
// (test_util.h). Expected behaviour from geometry and the laws of Coulomb and Newton.

namespace {
using testing_util::forEachSeed;
using testing_util::RandomGeometry;
}  // namespace

TEST(Task6_1_PlaneConstraint, RandomOrientationsAndScales) {
    // A plane in any orientation: the particle's distance to it is measured along the plane's normal
    // (not as a height), and a constraint exists exactly when p ends closer than h.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const double s = G.scale(), h = s * G.logUniform(1e-3, 1e-1), dt = G.logUniform(1e-4, 1e-2);
        const PlaneCollider c = plane(G.point(5.0 * s), G.unitVector(), G.uniform(0.0, 1.0), G.uniform(0.0, 1.0));
        const Vec3 t = G.perpendicularTo(c.normal);
        const Vec3 x = c.point + s * G.uniform(-3, 3) * t + s * G.uniform(0.2, 2.0) * c.normal;
        const double end = s * G.uniform(-2.0, 2.0);  // signed distance of p from the plane
        const Vec3 p = c.point + s * G.uniform(-3, 3) * G.perpendicularTo(c.normal) + end * c.normal;
        CollisionConstraint cc;
        const bool hit = generatePlaneConstraint(5, x, p, c, h, dt, &cc);
        std::ostringstream in;
        in << "plane through " << str(c.point) << " with normal " << str(c.normal) << ", x = " << str(x) << ", p = " << str(p)
           << " (p is " << end << " m from the plane along its normal), h = " << h << " m";
        if (hit != (end < h))
            return testing::AssertionFailure() << "A constraint must be generated exactly when p ends closer to the plane than the "
                                                  "thickness h, measured along the plane's normal (the plane may be tilted in any "
                                                  "direction): " << in.str() << "; yours says " << (hit ? "hit" : "no hit") << ".";
        if (hit && ((cc.n - c.normal).norm() > 1e-12 || std::abs((cc.q - c.point).dot(c.normal)) > 1e-9 * s ||
                    (cc.start - x).norm() > 1e-12 * (x.norm() + s) ||
                    std::abs(cc.vnBefore - (p - x).dot(c.normal) / dt) > 1e-9 * (p - x).norm() / dt))
            return testing::AssertionFailure() << "The constraint of a tilted plane must have n_s = the plane's normal, q_s on the plane, "
                                                  "start = x and vnBefore = (p - x).n_s / dt: " << in.str() << "; got n_s = "
                                               << str(cc.n) << ", q_s = " << str(cc.q) << ", vnBefore = " << cc.vnBefore << " m/s.";
        return testing::AssertionSuccess();
    });
}

TEST(Task6_2_SphereConstraint, ObliquePathsEnterAnywhere) {
    // A path that enters the inflated sphere (radius R + h) obliquely at a random point e (not aimed at the
    // centre), ending inside or beyond the sphere: the normal is the sphere's normal at e, wherever x and p are.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const double s = G.scale(), dt = G.logUniform(1e-4, 1e-2);
        const SphereCollider c = sphere(G.point(5.0 * s), s * G.uniform(0.5, 2.0), G.uniform(0, 1), G.uniform(0, 1));
        const double h = s * G.logUniform(1e-3, 1e-1), Rh = c.radius + h;
        const Vec3 ne = G.unitVector(), e = c.center + Rh * ne;             // entry point and its normal
        const double alpha = G.uniform(0.15, 1.35);                         // angle to the inward normal
        const Vec3 u = -std::cos(alpha) * ne + std::sin(alpha) * G.perpendicularTo(ne);  // unit direction of the path
        const Vec3 x = e - s * G.uniform(0.1, 2.0) * u;
        const Vec3 p = e + 2.0 * Rh * std::cos(alpha) * G.uniform(0.05, 1.5) * u;  // chord length 2 Rh cos(alpha)
        CollisionConstraint cc;
        const bool hit = generateSphereConstraint(1, x, p, c, h, dt, &cc);
        std::ostringstream in;
        in << "sphere around " << str(c.center) << ", R = " << c.radius << " m, h = " << h << " m, path x = " << str(x) << " -> p = "
           << str(p) << ", entering at " << str(e) << " at " << alpha << " rad to the inward normal";
        if (!hit)
            return testing::AssertionFailure() << "A path that enters the sphere (radius R + h) obliquely must give a constraint: "
                                               << in.str() << ".";
        if ((cc.n - ne).norm() > 1e-6 || (cc.q - (c.center + c.radius * ne)).norm() > 1e-6 * s)
            return testing::AssertionFailure() << "n_s must be the sphere's normal where the path enters, " << str(ne)
                                               << ", and q_s = c + R n_s = " << str(c.center + c.radius * ne)
                                               << " (not the normal towards x or p, which agree only for a path aimed at the "
                                                  "centre): " << in.str() << "; got n_s = " << str(cc.n) << ", q_s = " << str(cc.q) << ".";
        return testing::AssertionSuccess();
    });
}

TEST(Task6_4_VelocityUpdate, ObliqueLandingObeysCoulombAndRestitution) {
    // A particle lands obliquely on a tilted plane during the step (x above the thickness, p below), friction
    // mu and restitution e random. After generate, project and v = (p - x)/dt: the particle rests at the
    // thickness; then velocityUpdate applies Newton's restitution law (it leaves with at least e times the
    // incoming normal speed) and Coulomb's law for the impulses: the tangential velocity shrinks in its own
    // direction by mu times the normal velocity change of the solve, and stops rather than reverses.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const double s = G.scale(), dt = 1e-2, h = s * G.logUniform(1e-3, 1e-1);
        const PlaneCollider c = plane(G.point(5.0 * s), G.unitVector(), G.uniform(0.0, 1.5), G.uniform(0.0, 1.0));
        const Vec3 t = G.perpendicularTo(c.normal);
        const Vec3 x = c.point + s * G.uniform(-3, 3) * G.perpendicularTo(c.normal) + (h + s * G.uniform(0.01, 0.5)) * c.normal;
        const double vin = (s / dt) * G.uniform(1.0, 3.0);  // normal speed: x + dt v is below the surface
        const Vec3 v0 = -vin * c.normal + vin * G.uniform(0.2, 3.0) * t;
        const Vec3 p = x + dt * v0;
        CollisionConstraint cc;
        if (!generatePlaneConstraint(0, x, p, c, h, dt, &cc))
            return testing::AssertionFailure() << "p = " << str(p) << " is below the plane through " << str(c.point) << " with normal "
                                               << str(c.normal) << ": a constraint must be generated.";
        const Vec3 pp = p + projectCollisionConstraint(p, 1.0, h, cc);
        std::ostringstream in;
        in << "plane through " << str(c.point) << " with normal " << str(c.normal) << ", mu = " << c.friction
           << ", e = " << c.restitution << ", h = " << h << " m, x = " << str(x) << ", velocity " << str(v0) << " m/s, dt = " << dt << " s";
        if (std::abs((pp - c.point).dot(c.normal) - h) > 1e-9 * s)
            return testing::AssertionFailure() << "After the projection the particle must rest at the thickness h from the plane: it is "
                                               << (pp - c.point).dot(c.normal) << " m from it; " << in.str() << ".";
        Matrix3X v(3, 1);
        v.col(0) = (pp - x) / dt;
        const Vec3 vs = v.col(0);                     // after the solve
        const double vnBefore = v0.dot(c.normal);     // incoming normal velocity (negative)
        const double dvn = vs.dot(c.normal) - vnBefore;  // normal velocity change of the solve (>= 0)
        const Vec3 vts = vs - vs.dot(c.normal) * c.normal;
        velocityUpdate(v, {cc});
        const Vec3 vf = v.col(0), vtf = vf - vf.dot(c.normal) * c.normal;
        const double wantN = std::max(vs.dot(c.normal), -c.restitution * vnBefore);
        if (!vf.allFinite() || std::abs(vf.dot(c.normal) - wantN) > 1e-9 * vin)
            return testing::AssertionFailure() << "Restitution: the particle must leave the plane with the normal velocity max(v_n, "
                                                  "e |v_n,before|) = " << wantN << " m/s (incoming " << vnBefore << " m/s); got "
                                               << vf.dot(c.normal) << " m/s; " << in.str() << ".";
        const double wantT = std::max(0.0, vts.norm() - c.friction * dvn);
        if (std::abs(vtf.norm() - wantT) > 1e-9 * vin || (vtf - vtf.norm() * vts.normalized()).norm() > 1e-9 * vin)
            return testing::AssertionFailure()
                   << "Coulomb friction: the tangential velocity " << str(vts) << " m/s must shrink in its own direction by mu times "
                      "the normal velocity change of the solve, " << c.friction << " x " << dvn << " m/s, to " << wantT
                   << " m/s (never reversing, never sideways); got " << str(vtf) << " m/s (speed " << vtf.norm()
                   << "). The normal velocity change is v_n after the solve minus v_n before, not the incoming speed; "
                   << in.str() << ".";
        return testing::AssertionSuccess();
    });
}

TEST(Task6_4_CollisionSteps, InclineInAnyOrientationSlidesWithTheAnalyticAcceleration) {
    // The incline of BlockOnAnInclineSlidesWithTheAnalyticAcceleration with everything (slope and gravity)
    // rotated at random, a random slope angle, mu below tan(theta) and thickness: after 1 s the block has
    // slid a t^2 / 2 with a = g (sin(theta) - mu cos(theta)), and stays at the thickness from the slope.
    forEachSeed([](unsigned seed) -> testing::AssertionResult {
        RandomGeometry G(seed);
        const double theta = G.uniform(0.2, 0.9), mu = G.uniform(0.0, 0.8) * std::tan(theta), h = G.logUniform(1e-4, 1e-1);
        const double dt = 1e-3, T = 0.5;
        const Eigen::Matrix3d R = G.rotation();
        const Vec3 n = R * Vec3(-std::sin(theta), std::cos(theta), 0), g = R * kG, origin = G.point(10.0);
        const std::vector<AnyCollider> cols = {plane(origin, n, mu)};
        Particles P;
        P.x = Matrix3X(3, 1);
        P.x.col(0) = origin + h * n;
        P.v = Matrix3X::Zero(3, 1);
        P.w = VectorX::Ones(1);
        const int steps = static_cast<int>(std::lround(T / dt));
        for (int k = 0; k < steps; ++k) {  // the step above with gravity g instead of kG
            P.v.col(0) += dt * (g - kG);
            step(P, cols, h, dt, 4);
        }
        const double a = 9.81 * (std::sin(theta) - mu * std::cos(theta)), want = 0.5 * a * T * T;
        const double dist = (P.x.col(0) - origin - h * n).norm();
        if (!P.x.allFinite() || std::abs(dist - want) > 0.02 * want + 1e-3 * T * T ||
            std::abs((P.x.col(0) - origin).dot(n) - h) > 1e-9 + 1e-9 * dist)
            return testing::AssertionFailure() << "A block on an incline in any orientation (normal " << str(n) << ", gravity " << str(g)
                                               << " m/s^2, slope " << theta << " rad, mu = " << mu << ", h = " << h
                                               << " m) must slide a t^2/2 = " << want << " m in " << T << " s and stay at the "
                                                  "thickness from the slope; it slid " << dist << " m and is "
                                               << (P.x.col(0) - origin).dot(n) << " m from the slope.";
        return testing::AssertionSuccess();
    });
}

// ================================ Experiment (answers.json) ===================================
// The stage's experiment (task sheet, "Experiment"): predict from theory, measure with your own code,
// explain the difference, in exercises/06_collision/answers.json. This test checks only that the file is
// complete and well formed; the numbers are graded by the instructor.
TEST(Experiments, AnswerFileIsComplete) {
    EXPECT_TRUE(testing_util::answerFileIsComplete("06_collision", {"rebound_height"}, {"rebound_height"}));
}
