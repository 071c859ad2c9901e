// Camera matrices (OpenGL conventions), fitting and picking; pure Eigen.
#include "clothlab/render/camera.h"

#include <algorithm>
#include <cmath>

namespace clothlab {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

Eigen::Matrix4d Camera::view() const {
    const Vec3 f = (target - eye).normalized();
    Vec3 s = f.cross(up);
    if (s.norm() < 1e-12) s = f.cross(Vec3(0, 0, 1));  // looking along up: any side vector
    s.normalize();
    const Vec3 u = s.cross(f);
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.block<1, 3>(0, 0) = s.transpose();
    m.block<1, 3>(1, 0) = u.transpose();
    m.block<1, 3>(2, 0) = -f.transpose();
    m(0, 3) = -s.dot(eye);
    m(1, 3) = -u.dot(eye);
    m(2, 3) = f.dot(eye);
    return m;
}

Eigen::Matrix4d Camera::projection(double aspect) const {
    const double f = 1.0 / std::tan(fovy * kPi / 360.0);
    Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
    p(0, 0) = f / aspect;
    p(1, 1) = f;
    p(2, 2) = (zfar + znear) / (znear - zfar);
    p(2, 3) = 2.0 * zfar * znear / (znear - zfar);
    p(3, 2) = -1.0;
    return p;
}

Vec3 Camera::project(const Vec3& p, int width, int height) const {
    const Eigen::Vector4d c = projection(double(width) / height) * view() * p.homogeneous();
    const Vec3 ndc = c.head<3>() / c[3];
    return {(ndc.x() + 1) * 0.5 * width, (1 - (ndc.y() + 1) * 0.5) * height, (ndc.z() + 1) * 0.5};
}

Vec3 Camera::unproject(double px, double py, double depth, int width, int height) const {
    const Eigen::Matrix4d inv = (projection(double(width) / height) * view()).inverse();
    const Eigen::Vector4d ndc(2 * px / width - 1, 1 - 2 * py / height, 2 * depth - 1, 1);
    const Eigen::Vector4d w = inv * ndc;
    return w.head<3>() / w[3];
}

void Camera::orbit(double yaw, double pitch) {
    const Vec3 off = eye - target;
    const double r = off.norm();
    double elev = std::asin(std::clamp(off.y() / r, -1.0, 1.0));
    double azim = std::atan2(off.x(), off.z());
    azim += yaw;
    elev = std::clamp(elev + pitch, -1.45, 1.45);
    eye = target + r * Vec3(std::cos(elev) * std::sin(azim), std::sin(elev), std::cos(elev) * std::cos(azim));
}

void Camera::zoom(double factor) {
    eye = target + (eye - target) * factor;
    const double r = (eye - target).norm();
    znear = std::max(1e-3, r * 0.01);
    zfar = r * 100;
}

void drawBounds(const DrawData& d, Vec3& lo, Vec3& hi) {
    lo = Vec3::Constant(1e300);
    hi = Vec3::Constant(-1e300);
    for (int i = 0; i < d.x.cols(); ++i) {
        lo = lo.cwiseMin(d.x.col(i));
        hi = hi.cwiseMax(d.x.col(i));
    }
    for (const Collider& c : d.colliders)
        if (c.type == Collider::Type::Sphere) {
            lo = lo.cwiseMin(c.point - Vec3::Constant(c.radius));
            hi = hi.cwiseMax(c.point + Vec3::Constant(c.radius));
        }
    for (const Matrix3X& corners : d.collider_triangles)
        if (corners.cols() > 0) {
            lo = lo.cwiseMin(corners.rowwise().minCoeff());
            hi = hi.cwiseMax(corners.rowwise().maxCoeff());
        }
    if (lo.x() > hi.x()) lo = hi = Vec3::Zero();
}

Camera fitCamera(const Vec3& lo, const Vec3& hi, double aspect) {
    Camera cam;
    const Vec3 c = 0.5 * (lo + hi);
    const Vec3 ext = hi - lo;
    const double r = std::max(0.5 * ext.norm(), 0.05);
    const bool flat = ext.z() < 1e-6 * std::max(1.0, ext.norm());
    const Vec3 dir = (flat ? Vec3(0.25, 0.18, 1.0) : Vec3(0.55, 0.45, 1.0)).normalized();
    const double half = std::min(cam.fovy, 2 * std::atan(std::tan(cam.fovy * kPi / 360) * aspect) * 180 / kPi) * kPi / 360;
    double dist = r / std::sin(half) * 1.25;  // the bounding sphere plus a margin: sees everything
    cam.target = c;
    cam.eye = c + dist * dir;
    // Then move closer until the box's corners fill about 75 % of the view (a few fixed-point steps),
    // leaving room for markers and the overlay text.
    for (int it = 0; it < 6; ++it) {
        const Eigen::Matrix4d pv = cam.projection(aspect) * cam.view();
        double m = 0.0;
        for (int k = 0; k < 8; ++k) {
            const Vec3 p((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(), (k & 4) ? hi.z() : lo.z());
            const Eigen::Vector4d q = pv * p.homogeneous();
            if (q[3] <= 0) { m = 10; break; }
            m = std::max({m, std::abs(q[0] / q[3]), std::abs(q[1] / q[3])});
        }
        const double f = std::clamp(m / 0.75, 0.5, 2.0);
        if (std::abs(f - 1) < 0.01) break;
        dist *= f;
        cam.eye = c + dist * dir;
    }
    cam.znear = std::max(1e-3, dist * 0.01);
    cam.zfar = dist * 100;
    return cam;
}

Camera sceneCamera(const Scene& scene, const Vec3& lo, const Vec3& hi, double aspect) {
    if (!scene.view.camera) return fitCamera(lo, hi, aspect);
    Camera cam;
    cam.eye = scene.view.eye;
    cam.target = scene.view.target;
    cam.fovy = scene.view.fov;
    const double dist = (cam.eye - cam.target).norm();
    cam.znear = std::max(1e-3, dist * 0.01);
    cam.zfar = dist * 100;
    return cam;
}

int pickParticle(const DrawData& d, const Camera& cam, double px, double py, int width, int height, double radius) {
    const Eigen::Matrix4d pv = cam.projection(double(width) / height) * cam.view();
    int best = -1;
    double best_d2 = radius * radius, best_z = 1e300;
    for (int i = 0; i < d.x.cols(); ++i) {
        const Eigen::Vector4d c = pv * d.x.col(i).homogeneous();
        if (c[3] <= 0) continue;
        const double sx = (c[0] / c[3] + 1) * 0.5 * width, sy = (1 - (c[1] / c[3] + 1) * 0.5) * height;
        const double d2 = (sx - px) * (sx - px) + (sy - py) * (sy - py);
        // Prefer the nearest to the cursor; among (almost) equally near ones, the one in front.
        if (d2 < best_d2 - 1.0 || (d2 <= best_d2 + 1.0 && c[3] < best_z && d2 <= radius * radius)) {
            best = i, best_d2 = std::min(best_d2, d2), best_z = c[3];
        }
    }
    return best;
}

}  // namespace clothlab
