#include "clothlab/sim/colliders.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

namespace clothlab {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Any unit vector perpendicular to a (non-zero) vector.
Vec3 perpendicular(const Vec3& a) {
    const Vec3 t = std::abs(a.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    return a.cross(t).normalized();
}

}  // namespace

Vec3 closestOnTriangle(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c, int* feature) {
    const Vec3 ab = b - a, ac = c - a, ax = x - a;
    const double d1 = ab.dot(ax), d2 = ac.dot(ax);
    if (d1 <= 0 && d2 <= 0) return *feature = 0, a;
    const Vec3 bx = x - b;
    const double d3 = ab.dot(bx), d4 = ac.dot(bx);
    if (d3 >= 0 && d4 <= d3) return *feature = 1, b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return *feature = 3, a + d1 / (d1 - d3) * ab;
    const Vec3 cx = x - c;
    const double d5 = ab.dot(cx), d6 = ac.dot(cx);
    if (d6 >= 0 && d5 <= d6) return *feature = 2, c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return *feature = 5, a + d2 / (d2 - d6) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return *feature = 4, b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
    const double s = 1.0 / (va + vb + vc);
    return *feature = 6, a + ab * (vb * s) + ac * (vc * s);
}

namespace {

/// Squared distance from x to an axis-aligned box (0 inside).
double boxDistance2(const Vec3& x, const Vec3& lo, const Vec3& hi) {
    return (lo - x).cwiseMax(x - hi).cwiseMax(0.0).squaredNorm();
}

/// q, n, d from the closest point q and an outward direction `out` used when x is on the surface.
SurfacePoint fromClosest(const Vec3& x, const Vec3& q, const Vec3& out) {
    SurfacePoint s;
    s.q = q;
    const Vec3 r = x - q;
    const double len = r.norm();
    const bool outside = r.dot(out) >= 0.0;
    s.d = outside ? len : -len;
    s.n = len > 1e-12 ? Vec3((outside ? 1.0 : -1.0) * r / len) : out.normalized();
    return s;
}

SurfacePoint boxSurface(const Collider& c, const Vec3& x) {
    const Vec3 y = c.rotation.transpose() * (x - c.point), e = c.halfExtents;
    const Vec3 u = y.cwiseAbs() - e;
    SurfacePoint s;
    if ((u.array() > 0).any()) {  // outside: the clamped point
        const Vec3 q = y.cwiseMax(-e).cwiseMin(e), r = y - q;
        s.d = r.norm();
        s.q = c.point + c.rotation * q;
        s.n = c.rotation * (r / s.d);
        return s;
    }
    int k = 0;  // inside or on it: the nearest face
    u.maxCoeff(&k);
    Vec3 q = y, n = Vec3::Zero();
    const double side = y[k] >= 0 ? 1.0 : -1.0;
    q[k] = side * e[k];
    n[k] = side;
    s.d = u[k];
    s.q = c.point + c.rotation * q;
    s.n = c.rotation * n;
    return s;
}

SurfacePoint capsuleSurface(const Collider& c, const Vec3& x) {
    const Vec3 axis = c.end - c.point;
    const double t = std::clamp((x - c.point).dot(axis) / axis.squaredNorm(), 0.0, 1.0);
    const Vec3 s = c.point + t * axis, r = x - s;
    SurfacePoint out;
    out.n = r.norm() > 1e-12 ? Vec3(r.normalized()) : perpendicular(axis);
    out.q = s + c.radius * out.n;
    out.d = r.norm() - c.radius;
    return out;
}

}  // namespace

MeshShape::MeshShape(TriangleMesh mesh) : mesh_(std::move(mesh)) {
    const auto T = mesh_.triangles.size();
    faceNormal_ = triangleNormals(mesh_);
    edgeNormal_ = Matrix3X::Zero(3, static_cast<Eigen::Index>(3 * T));
    vertexNormal_ = Matrix3X::Zero(3, mesh_.vertices.cols());
    std::map<std::pair<int, int>, Vec3> edgeSum;  // sum of the normals of the (one or two) faces at an edge
    for (size_t t = 0; t < T; ++t) {
        const auto& f = mesh_.triangles[t];
        for (int k = 0; k < 3; ++k) {
            const auto [it, fresh] = edgeSum.try_emplace(std::minmax(f[k], f[(k + 1) % 3]), Vec3::Zero());  // Eigen does not zero
            it->second += faceNormal_.col(static_cast<Eigen::Index>(t));
            const Vec3 a = mesh_.vertices.col(f[(k + 1) % 3]) - mesh_.vertices.col(f[k]);
            const Vec3 b = mesh_.vertices.col(f[(k + 2) % 3]) - mesh_.vertices.col(f[k]);
            const double angle = std::atan2(a.cross(b).norm(), a.dot(b));  // the face's angle at vertex f[k]
            vertexNormal_.col(f[k]) += angle * faceNormal_.col(static_cast<Eigen::Index>(t));
        }
    }
    for (size_t t = 0; t < T; ++t)
        for (int k = 0; k < 3; ++k)
            edgeNormal_.col(static_cast<Eigen::Index>(3 * t + k)) = edgeSum[std::minmax(mesh_.triangles[t][k], mesh_.triangles[t][(k + 1) % 3])];
    order_.resize(T);
    std::iota(order_.begin(), order_.end(), 0);
    nodes_.reserve(T / 2 + 1);
    build(0, static_cast<int>(T));
    boxLo_.resize(3, static_cast<Eigen::Index>(T));
    boxHi_.resize(3, static_cast<Eigen::Index>(T));
    for (size_t k = 0; k < T; ++k) {
        const auto& f = mesh_.triangles[static_cast<size_t>(order_[k])];
        const Vec3 a = mesh_.vertices.col(f[0]), b = mesh_.vertices.col(f[1]), c = mesh_.vertices.col(f[2]);
        boxLo_.col(static_cast<Eigen::Index>(k)) = a.cwiseMin(b).cwiseMin(c);
        boxHi_.col(static_cast<Eigen::Index>(k)) = a.cwiseMax(b).cwiseMax(c);
    }
}

int MeshShape::build(int first, int count) {
    const int id = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
    for (int k = first; k < first + count; ++k)
        for (int j = 0; j < 3; ++j) {
            const Vec3 v = mesh_.vertices.col(mesh_.triangles[static_cast<size_t>(order_[static_cast<size_t>(k)])][j]);
            lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
        }
    nodes_[static_cast<size_t>(id)].lo = lo;
    nodes_[static_cast<size_t>(id)].hi = hi;
    if (count <= 4) {
        nodes_[static_cast<size_t>(id)].first = first;
        nodes_[static_cast<size_t>(id)].count = count;
        return id;
    }
    int axis = 0;  // split at the median centroid along the longest side
    (hi - lo).maxCoeff(&axis);
    const auto centroid = [&](int t) {
        const auto& f = mesh_.triangles[static_cast<size_t>(t)];
        return mesh_.vertices(axis, f[0]) + mesh_.vertices(axis, f[1]) + mesh_.vertices(axis, f[2]);
    };
    const int half = count / 2;
    std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                     [&](int a, int b) { return centroid(a) < centroid(b); });
    const int left = build(first, half);
    const int right = build(first + half, count - half);
    nodes_[static_cast<size_t>(id)].left = left;
    nodes_[static_cast<size_t>(id)].right = right;
    return id;
}

// The nearer child first, boxes and triangles farther than the best so far skipped: the first
// triangle in this order at the least distance wins. A bound2 above that distance only skips boxes
// and triangles that could not win, so every bound2 that finds a triangle finds the same one. (A box
// is skipped only when it is farther by a relative 1e-9, so that rounding in a triangle's distance,
// 1e-16 relative, cannot make a skipped triangle the winner.)
bool MeshShape::search(const Vec3& x, double bound2, SurfacePoint* out) const {
    constexpr double kMargin = 1.0 + 1e-9;
    double best = bound2;
    Vec3 q = Vec3::Zero(), pseudo = Vec3::UnitY();
    bool found = false;
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[static_cast<size_t>(stack[--top])];
        if (boxDistance2(x, node.lo, node.hi) > kMargin * best) continue;
        if (node.left < 0) {
            for (int k = node.first; k < node.first + node.count; ++k) {
                // a triangle is no nearer than its box
                if (boxDistance2(x, boxLo_.col(k), boxHi_.col(k)) > kMargin * best) continue;
                const int t = order_[static_cast<size_t>(k)];
                const auto& f = mesh_.triangles[static_cast<size_t>(t)];
                int feature = 6;
                const Vec3 c = closestOnTriangle(x, mesh_.vertices.col(f[0]), mesh_.vertices.col(f[1]), mesh_.vertices.col(f[2]), &feature);
                const double d2 = (x - c).squaredNorm();
                if (d2 < best) {
                    best = d2, q = c, found = true;
                    pseudo = feature < 3 ? vertexNormal_.col(f[feature])
                             : feature < 6 ? edgeNormal_.col(3 * t + feature - 3)
                                           : faceNormal_.col(t);
                }
            }
            continue;
        }
        const Node& a = nodes_[static_cast<size_t>(node.left)];
        const Node& b = nodes_[static_cast<size_t>(node.right)];
        const bool aFirst = boxDistance2(x, a.lo, a.hi) <= boxDistance2(x, b.lo, b.hi);
        stack[top++] = aFirst ? node.right : node.left;  // the nearer child is searched first
        stack[top++] = aFirst ? node.left : node.right;
    }
    if (found) *out = fromClosest(x, q, pseudo);
    return found;
}

SurfacePoint MeshShape::closest(const Vec3& x) const {
    SurfacePoint s;
    if (!search(x, INFINITY, &s)) s = fromClosest(x, Vec3::Zero(), Vec3::UnitY());  // no triangles
    return s;
}

SurfacePoint MeshShape::closest(const Vec3& x, const Vec3& near) const {
    // near is on the surface, so the closest point is at most |x − near| away; 1 nm more covers rounding
    // (and if no triangle is found below the bound after all, the full search decides)
    const double r = (x - near).norm() + 1e-9;
    if (!std::isfinite(r)) return closest(x);  // no point given (NaN)
    SurfacePoint s;
    return search(x, r * r, &s) ? s : closest(x);
}

SurfacePoint colliderSurface(const Collider& c, const Vec3& x) {
    switch (c.type) {
        case Collider::Type::Plane: return fromClosest(x, x - (x - c.point).dot(c.normal) * c.normal, c.normal);
        case Collider::Type::Sphere: {
            const Vec3 r = x - c.point;
            const Vec3 n = r.norm() > 1e-12 ? Vec3(r.normalized()) : Vec3::UnitY();
            return {c.point + c.radius * n, n, r.norm() - c.radius};
        }
        case Collider::Type::Box: return boxSurface(c, x);
        case Collider::Type::Capsule: return capsuleSurface(c, x);
        case Collider::Type::Mesh: return c.shape->closest(x);
    }
    return {};
}

SurfacePoint colliderSurface(const Collider& c, const Vec3& x, const Vec3& near) {
    return c.type == Collider::Type::Mesh ? c.shape->closest(x, near) : colliderSurface(c, x);
}

double colliderDistance(const Collider& c, const Vec3& x) {
    switch (c.type) {
        case Collider::Type::Plane: return (x - c.point).dot(c.normal);
        case Collider::Type::Sphere: return (x - c.point).norm() - c.radius;
        default: return colliderSurface(c, x).d;
    }
}

bool generateSolidConstraint(int i, const Vec3& x, const Vec3& p, const Collider& collider, double h, double dt,
                             CollisionConstraint* out, Vec3* near) {
    // Every query after the first is bounded by the closest point found before (the result is the same).
    SurfacePoint s = near ? colliderSurface(collider, x, *near) : colliderSurface(collider, x);  // NaN: no point
    struct Keep {  // hands the last closest point back through near, on every return
        Vec3* near;
        const SurfacePoint& s;
        ~Keep() { if (near) *near = s.q; }
    } keep{near, s};
    const double length = (p - x).norm();
    if (s.d < h) {  // starts within the thickness: only a prediction that stays within it
        s = colliderSurface(collider, p, s.q);  // (the closest point of x bounds the search)
        if (s.d >= h) return false;
    } else {  // sphere tracing along x -> p on d - h (d is 1-Lipschitz, so no step overshoots the surface)
        if (s.d - h >= length) return false;
        const double tolerance = 1e-9 + 1e-6 * h;
        double t = 0.0;
        bool hit = false;
        for (int k = 0; k < 100 && !hit; ++k) {
            t += (s.d - h) / length;
            if (t >= 1.0) break;
            s = colliderSurface(collider, x + t * (p - x), s.q);
            hit = s.d - h <= tolerance;
        }
        if (!hit) {  // grazing paths converge slowly: p itself decides
            s = colliderSurface(collider, p, s.q);
            if (s.d >= h) return false;
        }
    }
    *out = CollisionConstraint{i, s.q, s.n, x, (p - x).dot(s.n) / dt, collider.friction, collider.restitution};
    return true;
}

Matrix3X colliderTriangles(const Collider& c, int segments) {
    std::vector<Vec3> v;
    const auto quad = [&](const Vec3& a, const Vec3& b, const Vec3& cc, const Vec3& d) {
        v.insert(v.end(), {a, b, cc, a, cc, d});
    };
    if (c.type == Collider::Type::Box) {
        for (int k = 0; k < 3; ++k)
            for (const double side : {-1.0, 1.0}) {  // the face normal side * e_k; u, w span it counter-clockwise
                Vec3 n = Vec3::Zero(), u = Vec3::Zero(), w = Vec3::Zero();
                n[k] = side;
                u[(k + 1) % 3] = 1.0;
                w[(k + 2) % 3] = side;
                const auto corner = [&](double a, double b) {
                    return Vec3(c.point + c.rotation * (n + a * u + b * w).cwiseProduct(c.halfExtents));
                };
                quad(corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1));
            }
    } else if (c.type == Collider::Type::Capsule) {
        const Vec3 axis = (c.end - c.point).normalized(), e1 = perpendicular(axis), e2 = axis.cross(e1);
        const int rings = std::max(2, segments / 4);
        // A point of the capsule at angle a around the axis and latitude b in [-pi/2, pi/2] (cylinder between).
        const auto at = [&](int ia, int ib) {
            const double a = 2 * kPi * ia / segments;
            const int half = ib <= rings ? 0 : 1;  // ib in [0, 2 rings + 1]: lower cap, then upper cap
            const double b = -kPi / 2 + kPi / 2 * (ib - half) / rings;
            const Vec3 radial = std::cos(a) * e1 + std::sin(a) * e2;
            return Vec3((half ? c.end : c.point) + c.radius * (std::cos(b) * radial + std::sin(b) * axis));
        };
        for (int ib = 0; ib <= 2 * rings; ++ib)
            for (int ia = 0; ia < segments; ++ia) quad(at(ia, ib), at(ia + 1, ib), at(ia + 1, ib + 1), at(ia, ib + 1));
    } else if (c.type == Collider::Type::Mesh) {
        for (const auto& f : c.shape->mesh().triangles)
            for (int k = 0; k < 3; ++k) v.push_back(c.shape->mesh().vertices.col(f[k]));
    }
    Matrix3X out(3, static_cast<Eigen::Index>(v.size()));
    for (size_t k = 0; k < v.size(); ++k) out.col(static_cast<Eigen::Index>(k)) = v[k];
    return out;
}

}  // namespace clothlab
