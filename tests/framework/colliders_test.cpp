// Box, capsule and mesh colliders (framework, not graded): signed distance against brute force, no
// tunnelling at speed, and friction and restitution against the analytic results of stage 06
// (block on an incline: g (sin θ − μ cos θ); a dropped particle leaves with e times its impact speed). The step loop is
// written here (lines (5)-(16)) and calls the reference exercises 6.3 and 6.4 through the framework's
// CollisionConstraint, as the PBD solver does.
#include <cmath>
#include <ctime>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "clothlab/core/mesh.h"
#include "clothlab/sim/colliders.h"

using namespace clothlab;

namespace {

constexpr double kPi = 3.14159265358979323846;
const Vec3 kG(0, -9.81, 0);

// CPU time of this thread, s: the cost test below compares two costs, not wall times another process
// on the machine could stretch.
double threadSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

Eigen::Matrix3d rotZ(double degrees) { return Eigen::AngleAxisd(degrees * kPi / 180, Vec3::UnitZ()).toRotationMatrix(); }

Collider box(const Vec3& centre, const Vec3& half, const Eigen::Matrix3d& R, double mu = 0, double e = 0) {
    Collider c;
    c.type = Collider::Type::Box;
    c.point = centre, c.halfExtents = half, c.rotation = R, c.friction = mu, c.restitution = e;
    return c;
}
Collider capsule(const Vec3& a, const Vec3& b, double r, double mu = 0, double e = 0) {
    Collider c;
    c.type = Collider::Type::Capsule;
    c.point = a, c.end = b, c.radius = r, c.friction = mu, c.restitution = e;
    return c;
}
// The box as a closed triangle mesh (corners by bit pattern, faces counter-clockwise from outside).
TriangleMesh boxMesh(const Vec3& centre, const Vec3& half, const Eigen::Matrix3d& R) {
    TriangleMesh m;
    m.vertices.resize(3, 8);
    for (int i = 0; i < 8; ++i)
        m.vertices.col(i) = centre + R * Vec3((i & 1) ? half.x() : -half.x(), (i & 2) ? half.y() : -half.y(), (i & 4) ? half.z() : -half.z());
    for (const auto& q : {Eigen::Vector4i(0, 4, 6, 2), Eigen::Vector4i(1, 3, 7, 5), Eigen::Vector4i(0, 1, 5, 4),
                          Eigen::Vector4i(2, 6, 7, 3), Eigen::Vector4i(0, 2, 3, 1), Eigen::Vector4i(4, 5, 7, 6)}) {
        m.triangles.emplace_back(q[0], q[1], q[2]);
        m.triangles.emplace_back(q[0], q[2], q[3]);
    }
    return m;
}
Collider meshCollider(TriangleMesh m, double mu = 0, double e = 0) {
    EXPECT_EQ(meshProblem(m, false), "");
    Collider c;
    c.type = Collider::Type::Mesh;
    c.shape = std::make_shared<const MeshShape>(std::move(m));
    c.friction = mu, c.restitution = e;
    return c;
}

// Distance from x to triangle abc, computed differently from the collider code: the projection onto the
// plane if it falls inside (barycentric signs), else the nearest of the three edges as segments.
double segmentDistance(const Vec3& x, const Vec3& a, const Vec3& b) {
    const double t = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    return (x - a - t * (b - a)).norm();
}
double triangleDistance(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = (b - a).cross(c - a).normalized();
    const Vec3 p = x - (x - a).dot(n) * n;
    const bool inside = (b - a).cross(p - a).dot(n) >= 0 && (c - b).cross(p - b).dot(n) >= 0 && (a - c).cross(p - c).dot(n) >= 0;
    if (inside) return std::abs((x - a).dot(n));
    return std::min({segmentDistance(x, a, b), segmentDistance(x, b, c), segmentDistance(x, c, a)});
}

// Particles under gravity against one collider, lines (5)-(16) of the PBD loop.
struct Particle {
    Vec3 x, v;
};
void step(Particle& P, const Collider& c, double h, double dt) {
    P.v += dt * kG;
    Vec3 p = P.x + dt * P.v;
    CollisionConstraint cc;
    const bool hit = generateSolidConstraint(0, P.x, p, c, h, dt, &cc);
    for (int it = 0; it < 10 && hit; ++it) p += projectCollisionConstraint(p, 1.0, h, cc);  // exercise 6.3 (reference)
    Matrix3X v = (p - P.x) / dt;
    P.x = p;
    if (hit) velocityUpdate(v, {cc});  // exercise 6.4 (reference)
    P.v = v.col(0);
}

}  // namespace

// ---- signed distance -----------------------------------------------------------------------------------

TEST(Colliders, BoxDistanceMatchesBruteForce) {
    const Collider b = box(Vec3(0.3, -0.2, 0.1), Vec3(0.5, 0.2, 0.3), Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix());
    const TriangleMesh m = boxMesh(b.point, b.halfExtents, b.rotation);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.2, 1.2);
    for (int k = 0; k < 2000; ++k) {
        const Vec3 x(u(rng), u(rng), u(rng));
        double brute = INFINITY;  // distance to the surface: nearest of its 12 triangles
        for (const auto& t : m.triangles) brute = std::min(brute, triangleDistance(x, m.vertices.col(t[0]), m.vertices.col(t[1]), m.vertices.col(t[2])));
        const Vec3 y = b.rotation.transpose() * (x - b.point);
        const bool inside = (y.cwiseAbs().array() < b.halfExtents.array()).all();
        const double d = colliderDistance(b, x);
        ASSERT_NEAR(d, inside ? -brute : brute, 1e-12) << "at " << x.transpose();
        const SurfacePoint s = colliderSurface(b, x);
        ASSERT_NEAR((x - s.q).norm(), brute, 1e-12) << "q is the closest surface point";
        ASSERT_NEAR(s.n.norm(), 1.0, 1e-12);
    }
}

TEST(Colliders, CapsuleDistanceMatchesSampledAxis) {
    const Collider c = capsule(Vec3(0, 0, 0), Vec3(0.4, 1.0, -0.3), 0.05);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-0.5, 1.5);
    for (int k = 0; k < 300; ++k) {
        const Vec3 x(u(rng), u(rng), u(rng));
        double axis = INFINITY;  // distance to the axis, by 20001 samples of it (error < 1.2e-4 * 0.5 * step)
        for (int j = 0; j <= 20000; ++j) axis = std::min(axis, (x - (c.point + j / 20000.0 * (c.end - c.point))).norm());
        ASSERT_NEAR(colliderDistance(c, x), axis - c.radius, 1e-8) << "at " << x.transpose();
    }
}

TEST(Colliders, MeshDistanceMatchesBruteForceAndTheBox) {
    // A closed mesh: the same rotated box as the box collider; its signed distance must agree with the box's.
    const Collider b = box(Vec3(0, 1, 0), Vec3(0.6, 0.1, 0.4), rotZ(20));
    const Collider m = meshCollider(boxMesh(b.point, b.halfExtents, b.rotation));
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 2.0);
    for (int k = 0; k < 2000; ++k) {
        const Vec3 x(u(rng), u(rng), u(rng));
        ASSERT_NEAR(colliderDistance(m, x), colliderDistance(b, x), 1e-12) << "at " << x.transpose();
    }
}

TEST(Colliders, MeshOf10kTrianglesIsFastAndExact) {
    // A wavy sheet of 2 x 71 x 71 = 10082 triangles: the hierarchy's answer equals a scan over every triangle.
    TriangleMesh m;
    const int n = 72;
    m.vertices.resize(3, n * n);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) m.vertices.col(r * n + c) = Vec3(c / 35.5 - 1, 0.1 * std::sin(4.0 * c / n) * std::cos(5.0 * r / n), 1 - r / 35.5);
    for (int r = 0; r + 1 < n; ++r)
        for (int c = 0; c + 1 < n; ++c) {
            const int a = r * n + c;
            m.triangles.emplace_back(a, a + 1, a + n + 1);
            m.triangles.emplace_back(a, a + n + 1, a + n);
        }
    ASSERT_GE(m.triangles.size(), 10000u);
    const Collider col = meshCollider(m);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.3, 1.3);
    std::vector<Vec3> points;
    for (int k = 0; k < 200; ++k) points.emplace_back(u(rng), 0.5 * u(rng), u(rng));
    const double t0 = threadSeconds();
    std::vector<double> brute(points.size(), INFINITY);
    for (size_t k = 0; k < points.size(); ++k)
        for (const auto& t : m.triangles)
            brute[k] = std::min(brute[k], triangleDistance(points[k], m.vertices.col(t[0]), m.vertices.col(t[1]), m.vertices.col(t[2])));
    const double scanUs = 1e6 * (threadSeconds() - t0) / static_cast<double>(points.size());
    for (size_t k = 0; k < points.size(); ++k)
        ASSERT_NEAR(std::abs(colliderDistance(col, points[k])), brute[k], 1e-12) << "at " << points[k].transpose();
    // Cost: 4096 queries (one 64 x 64 cloth, one step) near the surface, against the scan above.
    const double t1 = threadSeconds();
    double sum = 0;
    for (int k = 0; k < 4096; ++k) sum += colliderDistance(col, Vec3(u(rng) * 0.8, 0.05 * u(rng), u(rng) * 0.8));
    const double us = 1e6 * (threadSeconds() - t1) / 4096;
    std::cout << "[ measure  ] mesh collider, " << m.triangles.size() << " triangles: " << us << " us per query, " << scanUs
              << " us for a scan of every triangle (sum " << sum << ")\n";
    EXPECT_LT(us, scanUs / 10) << "a query must not scan all triangles";
}

TEST(Colliders, MeshSearchFromANearbySurfacePointIsTheSameBitForBit) {
    // closest(x, near), as the solver and the run checks call it with a particle's last closest point,
    // must give closest(x) exactly: on the rotated box (ties at its edges and corners) and the scene's
    // dummy, with hints near x, far from x, on another part of the surface, and NaN (none).
    std::vector<TriangleMesh> meshes = {boxMesh(Vec3(0, 1, 0), Vec3(0.6, 0.1, 0.4), rotZ(20)),
                                        boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1), Eigen::Matrix3d::Identity())};
    meshes.push_back(loadObjMesh(std::string(CLOTHLAB_SOURCE_DIR) + "/scenes/meshes/mannequin.obj", "test", "mesh", false));
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (const TriangleMesh& m : meshes) {
        const MeshShape shape(m);
        const Vec3 lo = m.vertices.rowwise().minCoeff(), hi = m.vertices.rowwise().maxCoeff();
        const Vec3 mid = (lo + hi) / 2, half = (hi - lo) / 2;
        int same = 0;
        for (int k = 0; k < 3000; ++k) {
            const Vec3 x = mid + 1.3 * half.cwiseProduct(Vec3(u(rng), u(rng), u(rng)));
            const SurfacePoint ref = shape.closest(x);
            const Vec3 moved = x + 0.02 * half.norm() * Vec3(u(rng), u(rng), u(rng));
            const Vec3 other = mid + 1.3 * half.cwiseProduct(Vec3(u(rng), u(rng), u(rng)));
            for (const Vec3& near : {ref.q, shape.closest(moved).q, shape.closest(other).q, Vec3(Vec3::Constant(NAN))}) {
                const SurfacePoint s = shape.closest(x, near);
                ASSERT_TRUE(s.q == ref.q && s.n == ref.n && s.d == ref.d) << "at " << x.transpose() << ", near " << near.transpose();
                ++same;
            }
        }
        EXPECT_EQ(same, 12000);
    }
}

// ---- no tunnelling -------------------------------------------------------------------------------------

TEST(Colliders, FastParticleNeverEndsInside) {
    // Thin solids (a 2 cm plate, a 2 cm pole, a 2 cm mesh plate) and a particle at 30 m/s: at dt = 0.01 s it
    // moves 0.3 m per step, fifteen times the thickness, and must never end a step inside, nor below. Friction
    // μ = 2 holds it where it lands (a frictionless particle would slide off the tilted plate or the pole).
    const double h = 0.005;
    const std::vector<std::pair<std::string, Collider>> solids = {
        {"box", box(Vec3(0, 0, 0), Vec3(1, 0.01, 1), rotZ(10), 2.0)},
        {"capsule", capsule(Vec3(-1, 0, 0.0), Vec3(1, 0, 0.0), 0.01, 2.0)},
        {"mesh", meshCollider(boxMesh(Vec3(0, 0, 0), Vec3(1, 0.01, 1), rotZ(-10)), 2.0)},
    };
    for (const auto& [name, c] : solids)
        for (const double dt : {0.001, 0.005, 0.01, 0.02})
            for (const double offset : {0.0, 0.002, 0.004}) {
                Particle P{Vec3(offset, 1.0, offset), Vec3(0, -30, 0)};
                for (int n = 0; n < 200; ++n) {
                    const Vec3 before = P.x;
                    step(P, c, h, dt);
                    ASSERT_GE(colliderDistance(c, P.x), h - 1e-9) << name << ", dt " << dt << ": inside after step " << n;
                    for (int k = 1; k < 100; ++k)  // and the straight way from the last position did not cross the solid
                        ASSERT_GE(colliderDistance(c, before + k / 100.0 * (P.x - before)), 0.0)
                            << name << ", dt " << dt << ", offset " << offset << ": went through the solid in step " << n;
                }
            }
}

// ---- friction and restitution, as in stage 06 ------------------------------------------------------------

TEST(Colliders, BlockOnInclineSlidesWithCoulombFriction) {
    // A slope at θ = 30 degrees with μ = 0.3: s(t) = ½ g (sin θ − μ cos θ) t² along it (the top of a turned box,
    // the same top as a mesh, and the top line of a thick tilted capsule).
    const double theta = 30 * kPi / 180, mu = 0.3, h = 0.001, dt = 1e-3, T = 1.0;
    const Eigen::Matrix3d R = rotZ(30);
    const Vec3 down = R * Vec3(-1, 0, 0), top = R * Vec3(0, 1, 0);  // down the slope; outward normal of the top
    const std::vector<std::pair<std::string, Collider>> slopes = {
        {"box", box(Vec3(0, 0, 0), Vec3(5, 0.5, 5), R, mu)},
        {"mesh", meshCollider(boxMesh(Vec3(0, 0, 0), Vec3(5, 0.5, 5), R), mu)},
        {"capsule", capsule(R * Vec3(-5, -1.5, 0), R * Vec3(5, -1.5, 0), 2.0, mu)},
    };
    const double expected = 0.5 * 9.81 * (std::sin(theta) - mu * std::cos(theta)) * T * T;
    for (const auto& [name, c] : slopes) {
        const Vec3 start = R * Vec3(2, 0.5 + h, 0);
        Particle P{start, Vec3::Zero()};
        for (int n = 0; n < std::lround(T / dt); ++n) step(P, c, h, dt);
        EXPECT_NEAR((P.x - start).dot(down), expected, 0.03 * expected) << name;
        EXPECT_NEAR((P.x - start).dot(top), 0.0, 2 * h) << name << ": it stays on the surface";
    }
    // μ > tan θ: it sticks.
    Particle P{R * Vec3(2, 0.5 + h, 0), Vec3::Zero()};
    const Collider sticky = box(Vec3(0, 0, 0), Vec3(5, 0.5, 5), R, 0.7);
    for (int n = 0; n < 1000; ++n) step(P, sticky, h, dt);
    EXPECT_LT((P.x - R * Vec3(2, 0.5 + h, 0)).norm(), 1e-3) << "static friction holds it";
}

TEST(Colliders, DropLeavesWithEOfItsImpactSpeed) {
    const double e = 0.5, H = 1.0, h = 0.001, dt = 1e-4;
    const std::vector<std::pair<std::string, Collider>> floors = {
        {"box", box(Vec3(0, -0.5, 0), Vec3(2, 0.5, 2), Eigen::Matrix3d::Identity(), 0, e)},
        {"mesh", meshCollider(boxMesh(Vec3(0, -0.5, 0), Vec3(2, 0.5, 2), Eigen::Matrix3d::Identity()), 0, e)},
        {"capsule", capsule(Vec3(0, -1, -2), Vec3(0, -1, 2), 1.0, 0, e)},
    };
    for (const auto& [name, c] : floors) {
        Particle P{Vec3(0, H + h, 0), Vec3::Zero()};
        double before = 0.0, after = 0.0;  // the speeds of the step that turned the velocity upward, m/s
        for (int n = 0; n < 20000 && after == 0.0; ++n) {
            const double vy = P.v.y();
            step(P, c, h, dt);
            if (vy < 0 && P.v.y() > 0) before = -vy, after = P.v.y();
        }
        ASSERT_GT(after, 0.0) << name << ": the dropped particle must bounce";
        EXPECT_NEAR(after, e * before, 0.01 * e * before) << name << ": it must leave with e times its impact speed";
    }
}

// ---- drawing -----------------------------------------------------------------------------------------

TEST(Colliders, TrianglesForDrawingLieOnTheSurfaceAndFaceOut) {
    for (const Collider& c : {box(Vec3(1, 2, 3), Vec3(0.3, 0.2, 0.1), rotZ(25)), capsule(Vec3(0, 0, 0), Vec3(0, 2, 0.5), 0.1),
                              meshCollider(boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1), rotZ(5)))}) {
        const Matrix3X t = colliderTriangles(c, 24);
        ASSERT_GT(t.cols(), 0);
        ASSERT_EQ(t.cols() % 3, 0);
        for (Eigen::Index k = 0; k < t.cols(); k += 3) {
            const Vec3 centroid = (t.col(k) + t.col(k + 1) + t.col(k + 2)) / 3;
            const Vec3 n = (t.col(k + 1) - t.col(k)).cross(t.col(k + 2) - t.col(k));
            if (n.norm() < 1e-12) continue;  // a capsule's pole rows are slivers
            for (int j = 0; j < 3; ++j) EXPECT_NEAR(colliderDistance(c, t.col(k + j)), 0.0, 1e-9) << "corners on the surface";
            EXPECT_GT(colliderDistance(c, centroid + 1e-3 * n.normalized()), colliderDistance(c, centroid - 1e-3 * n.normalized()))
                << "counter-clockwise seen from outside";
        }
    }
}
