#pragma once
// An orbit camera: it looks at a focus point from a direction given by yaw and pitch and from a
// distance. The viewer turns mouse drags into orbit/pan/zoom; the CLI frames a scene's bounds.
// Matrices follow OpenGL conventions (right-handed view space, clip z in [-1, 1]).
#include <Eigen/Geometry>
#include <optional>

#include "animkit/core/types.h"

namespace animkit {

/// A half-line: the points origin + t direction for t >= 0, world space.
struct Ray {
  /// Where the ray starts, world space.
  Vec3 origin;
  Vec3 direction;  ///< unit
};

/// A camera orbiting a focus point: yaw and pitch give the direction it looks from, `distance`
/// how far away the eye is.
struct OrbitCamera {
  Vec3 focus = Vec3(0.0, 0.8, 0.0);  ///< world point the camera looks at
  double yaw = 0.6;                  ///< radians about +y; 0 looks from +z towards -z
  double pitch = 0.45;               ///< radians above the horizon, clamped to (-1.55, 1.55)
  double distance = 6.0;             ///< from the focus (scene units), > 0
  double fov_y = 0.7;                ///< vertical field of view (radians)

  /// The eye's world position: `distance` from the focus along
  /// (cos(pitch) sin(yaw), sin(pitch), cos(pitch) cos(yaw)).
  Vec3 eye() const;
  /// The view matrix (world to view space) as gluLookAt makes it: from eye() towards the
  /// focus, +y up.
  Eigen::Matrix4d view() const;
  /// Perspective projection for a viewport of the given aspect (width / height).
  Eigen::Matrix4d projection(double aspect) const;

  /// Mouse-drag orbit: radians to add to yaw and pitch (pitch is clamped).
  void orbit(double d_yaw, double d_pitch);
  /// Zoom by a factor (< 1 moves closer); the distance stays within [1e-3, 1e4].
  void zoom(double factor);
  /// Moves the focus within the view plane by a drag of (dx, dy) pixels in a viewport
  /// `viewport_height` pixels tall, so the point under the cursor follows the cursor.
  void pan(double dx_px, double dy_px, double viewport_height_px);

  /// The ray from the eye through pixel (x, y) of a width x height viewport (y down, as
  /// window systems report the mouse).
  Ray ray_through_pixel(double x, double y, double width, double height) const;
  /// Pixel coordinates (y down) of a world point; z is the NDC depth. Points behind the eye
  /// get a negative w, reported as nothing.
  std::optional<Eigen::Vector3d> project(const Vec3& world, double width, double height) const;

  /// A camera looking from (yaw, pitch) that fits `box` in a viewport of the given aspect with
  /// a margin (0.1 = 10% on each side).
  static OrbitCamera framing(const Eigen::AlignedBox3d& box, double aspect, double yaw,
                             double pitch, double margin = 0.08);
};

/// Where a ray meets the plane through `point` with normal `normal`, or nothing when it runs
/// parallel to the plane or points away from it.
std::optional<Vec3> intersect_plane(const Ray& ray, const Vec3& point, const Vec3& normal);
/// Where a ray meets the plane y = height (the drawing plane is y = 0).
std::optional<Vec3> intersect_horizontal_plane(const Ray& ray, double height);

}  // namespace animkit
