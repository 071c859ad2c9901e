/// @file camera.h
/// @brief A perspective camera: view and projection matrices (OpenGL conventions), fitting, picking.
///
/// Pure Eigen: the same matrices drive the renderer, the mouse picking in the app and the tests.
#pragma once
#include <Eigen/Core>

#include "clothlab/render/draw_data.h"

namespace clothlab {

/// A look-at camera with a vertical field of view.
struct Camera {
    Vec3 eye{0, 0, 3};     ///< camera position, m
    Vec3 target{0, 0, 0};  ///< point looked at, m
    Vec3 up{0, 1, 0};      ///< world up direction
    double fovy = 35.0;    ///< vertical field of view, degrees
    double znear = 0.01;   ///< near clipping distance, m
    double zfar = 100.0;   ///< far clipping distance, m

    /// World-to-eye matrix (gluLookAt): rows are the camera axes s, u, -f; translation -R eye.
    Eigen::Matrix4d view() const;
    /// Eye-to-clip matrix (gluPerspective) for a viewport of the given aspect ratio width/height.
    /// @param aspect  width / height
    Eigen::Matrix4d projection(double aspect) const;
    /// Pixel position of a world point: x right, y down, origin at the top-left corner; z = depth in [0, 1].
    /// @param p              world point, m
    /// @param width, height  viewport size in pixels
    Vec3 project(const Vec3& p, int width, int height) const;
    /// The world point on the ray through pixel (px, py) at the given window depth (inverse of project()).
    /// @param px, py         pixel position (top-left origin)
    /// @param depth          window depth in [0, 1]
    /// @param width, height  viewport size in pixels
    Vec3 unproject(double px, double py, double depth, int width, int height) const;
    /// Turns the eye around the target: yaw about the world up axis, pitch about the camera's right axis.
    /// @param yaw, pitch  angles in radians (pitch is clamped short of the poles)
    void orbit(double yaw, double pitch);
    /// Moves the eye towards the target by the factor (< 1: closer).
    /// @param factor  new distance / old distance
    void zoom(double factor);
};

/// Axis-aligned bounding box of the particles, plus spheres, boxes, capsules, meshes and (small) plane patches of the colliders.
/// @param d    what is drawn
/// @param lo   smallest corner (output), m
/// @param hi   largest corner (output), m
void drawBounds(const DrawData& d, Vec3& lo, Vec3& hi);

/// A camera that sees the box [lo, hi] whole, looking slightly from above and from the front-right
/// (or straight from the front for flat scenes in the x-y plane with no depth).
/// @param lo, hi  the box to frame, m
/// @param aspect  viewport width / height
Camera fitCamera(const Vec3& lo, const Vec3& hi, double aspect);

/// The scene's camera (view.eye/target/fov) when it sets one, else fitCamera() on the box.
/// @param scene   the scene
/// @param lo, hi  the box to frame when the scene sets no camera, m
/// @param aspect  viewport width / height
Camera sceneCamera(const Scene& scene, const Vec3& lo, const Vec3& hi, double aspect);

/// Index of the particle whose projection is nearest to pixel (px, py), within `radius` pixels; -1 if none.
/// @param d              particles
/// @param cam            camera
/// @param px, py         pixel (top-left origin)
/// @param width, height  viewport size
/// @param radius         search radius, pixels
int pickParticle(const DrawData& d, const Camera& cam, double px, double py, int width, int height, double radius);

}  // namespace clothlab
