#include "clothlab/sim/scene_checks.h"

#include <algorithm>
#include <cmath>

#include "clothlab/core/grid.h"
#include "clothlab/sim/colliders.h"
#include "clothlab/sim/simulation.h"

namespace clothlab {

namespace {

/// Whether the segment p–q crosses triangle abc (Möller–Trumbore, the parameter along p–q in [0, 1]).
bool segmentCrossesTriangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 d = q - p, e1 = b - a, e2 = c - a, s = d.cross(e2);
    const double det = e1.dot(s);
    if (std::abs(det) < 1e-300) return false;  // parallel to the triangle's plane
    const Vec3 t = p - a;
    const double u = t.dot(s) / det;
    if (u < 0 || u > 1) return false;
    const Vec3 r = t.cross(e1);
    const double v = d.dot(r) / det;
    if (v < 0 || u + v > 1) return false;
    const double along = e2.dot(r) / det;
    return along >= 0 && along <= 1;
}

}  // namespace

bool trianglesIntersect(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
    for (int k = 0; k < 3; ++k) {
        if (segmentCrossesTriangle(a.col(k), a.col((k + 1) % 3), b.col(0), b.col(1), b.col(2))) return true;
        if (segmentCrossesTriangle(b.col(k), b.col((k + 1) % 3), a.col(0), a.col(1), a.col(2))) return true;
    }
    return false;
}

std::vector<int> trianglesThroughCollider(const Matrix3X& x, const std::vector<Eigen::Vector3i>& triangles, const Collider& c) {
    std::vector<int> through;
    const auto corners = [&](const Eigen::Vector3i& t) {
        Eigen::Matrix3d m;
        for (int k = 0; k < 3; ++k) m.col(k) = x.col(t[k]);
        return m;
    };
    if (c.type == Collider::Type::Plane || c.type == Collider::Type::Sphere) {
        for (size_t i = 0; i < triangles.size(); ++i) {
            const Eigen::Matrix3d t = corners(triangles[i]);
            bool hit = false;
            if (c.type == Collider::Type::Plane) {
                for (int k = 0; k < 3; ++k) hit = hit || (t.col(k) - c.point).dot(c.normal) < 0;
            } else {
                int feature = 0;
                hit = (closestOnTriangle(c.point, t.col(0), t.col(1), t.col(2), &feature) - c.point).norm() < c.radius;
            }
            if (hit) through.push_back(static_cast<int>(i));
        }
        return through;
    }
    // Box, capsule, mesh: against the drawn triangles, each pair first through their bounding boxes.
    const Matrix3X drawn = colliderTriangles(c);
    const Eigen::Index nd = drawn.cols() / 3;
    Matrix3X lo(3, nd), hi(3, nd);
    for (Eigen::Index k = 0; k < nd; ++k) {
        lo.col(k) = drawn.middleCols(3 * k, 3).rowwise().minCoeff();
        hi.col(k) = drawn.middleCols(3 * k, 3).rowwise().maxCoeff();
    }
    for (size_t i = 0; i < triangles.size(); ++i) {
        const Eigen::Matrix3d t = corners(triangles[i]);
        const Vec3 tlo = t.rowwise().minCoeff(), thi = t.rowwise().maxCoeff();
        for (Eigen::Index k = 0; k < nd; ++k) {
            if ((tlo.array() > hi.col(k).array()).any() || (thi.array() < lo.col(k).array()).any()) continue;
            if (trianglesIntersect(t, drawn.middleCols(3 * k, 3))) {
                through.push_back(static_cast<int>(i));
                break;
            }
        }
    }
    return through;
}

Vec3 restNormal(const Matrix3X& rest, const std::vector<Eigen::Vector3i>& triangles) {
    Vec3 sum = Vec3::Zero();  // twice the area times the unit normal, summed
    for (const auto& t : triangles) sum += (rest.col(t[1]) - rest.col(t[0])).cross(rest.col(t[2]) - rest.col(t[0]));
    const double len = sum.norm();
    return len > 0 ? Vec3(sum / len) : Vec3::Zero();
}

NormalFlips normalFlips(const Matrix3X& x, const std::vector<Eigen::Vector3i>& triangles, const Vec3& normal) {
    NormalFlips f;
    for (const auto& t : triangles) {
        const Vec3 m = (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0]));
        const double len = m.norm();
        if (!(len > 0)) continue;
        const double c = m.dot(normal) / len;
        ++f.triangles;
        f.flipped += c < 0;
        f.lowest = std::min(f.lowest, c);
    }
    return f;
}

LookChecks lookChecks(const Simulation& sim) {
    LookChecks c;
    const Scene& s = sim.scene();
    const auto& tris = sim.triangles();
    if (s.model != Model::Cloth || tris.empty()) return c;
    const Matrix3X& x = sim.state().x;
    c.triangles = static_cast<int>(tris.size());
    c.through_applies = !s.colliders.empty();
    if (c.through_applies) {
        std::vector<char> hit(tris.size(), 0);
        for (const Collider& col : s.colliders)
            for (int t : trianglesThroughCollider(x, tris, col)) hit[static_cast<size_t>(t)] = 1;
        c.through = static_cast<int>(std::count(hit.begin(), hit.end(), 1));
    }
    bool pinned = false;
    for (int i = 0; i < sim.state().size(); ++i) pinned = pinned || sim.state().w[i] == 0.0;
    c.flips_applies = pinned && s.colliders.empty() && s.forces.wind.squaredNorm() == 0.0;
    if (c.flips_applies) {
        const State rest = makeClothGeometry(s.cloth).state;
        c.flips = normalFlips(x, tris, restNormal(rest.x, tris));
    }
    return c;
}

std::string lookChecksLine(const LookChecks& c) {
    std::string s;
    if (c.through_applies) s = std::to_string(c.through) + " of " + std::to_string(c.triangles) + " cloth triangles through a collider";
    if (c.flips_applies)
        s += (s.empty() ? "" : ", ") + std::to_string(c.flips.flipped) + " of " + std::to_string(c.flips.triangles) + " triangles turned over";
    return s;
}

}  // namespace clothlab
