#include "animkit/scene/orbit_camera.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace animkit {

namespace {
constexpr double kMaxPitch = 1.55;  // just short of straight up/down, where yaw degenerates
}

Vec3 OrbitCamera::eye() const {
  const Vec3 offset(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                    std::cos(pitch) * std::cos(yaw));
  return focus + distance * offset;
}

Eigen::Matrix4d OrbitCamera::view() const {
  // gluLookAt: rows are the camera's right, up and backward axes.
  const Vec3 e = eye();
  const Vec3 back = (e - focus).normalized();
  const Vec3 right = Vec3::UnitY().cross(back).normalized();
  const Vec3 up = back.cross(right);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = right.transpose();
  m.block<1, 3>(1, 0) = up.transpose();
  m.block<1, 3>(2, 0) = back.transpose();
  m(0, 3) = -right.dot(e);
  m(1, 3) = -up.dot(e);
  m(2, 3) = -back.dot(e);
  return m;
}

Eigen::Matrix4d OrbitCamera::projection(double aspect) const {
  // gluPerspective with near/far scaled to the distance, so zooming keeps depth precision.
  const double near_plane = 0.01 * distance, far_plane = 100.0 * distance;
  const double f = 1.0 / std::tan(0.5 * fov_y);
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  m(2, 2) = (far_plane + near_plane) / (near_plane - far_plane);
  m(2, 3) = 2.0 * far_plane * near_plane / (near_plane - far_plane);
  m(3, 2) = -1.0;
  return m;
}

void OrbitCamera::orbit(double d_yaw, double d_pitch) {
  yaw += d_yaw;
  pitch = std::clamp(pitch + d_pitch, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::zoom(double factor) {
  distance = std::clamp(distance * factor, 1e-3, 1e4);
}

void OrbitCamera::pan(double dx_px, double dy_px, double viewport_height_px) {
  // One pixel spans this many scene units at the focus distance.
  const double units_per_px = 2.0 * distance * std::tan(0.5 * fov_y) / viewport_height_px;
  const Eigen::Matrix4d v = view();
  const Vec3 right = v.block<1, 3>(0, 0).transpose();
  const Vec3 up = v.block<1, 3>(1, 0).transpose();
  focus += units_per_px * (-dx_px * right + dy_px * up);
}

Ray OrbitCamera::ray_through_pixel(double x, double y, double width, double height) const {
  const double ndc_x = 2.0 * x / width - 1.0;
  const double ndc_y = 1.0 - 2.0 * y / height;
  const double t = std::tan(0.5 * fov_y);
  const Eigen::Matrix4d v = view();
  const Vec3 right = v.block<1, 3>(0, 0).transpose();
  const Vec3 up = v.block<1, 3>(1, 0).transpose();
  const Vec3 back = v.block<1, 3>(2, 0).transpose();
  const Vec3 direction = ndc_x * t * (width / height) * right + ndc_y * t * up - back;
  return {eye(), direction.normalized()};
}

std::optional<Eigen::Vector3d> OrbitCamera::project(const Vec3& world, double width,
                                                    double height) const {
  const Eigen::Vector4d clip = projection(width / height) * view() * world.homogeneous();
  if (clip.w() <= 0.0) return std::nullopt;
  const Eigen::Vector3d ndc = clip.head<3>() / clip.w();
  return Eigen::Vector3d(0.5 * (ndc.x() + 1.0) * width, 0.5 * (1.0 - ndc.y()) * height, ndc.z());
}

OrbitCamera OrbitCamera::framing(const Eigen::AlignedBox3d& box, double aspect, double yaw,
                                 double pitch, double margin) {
  OrbitCamera camera;
  camera.yaw = yaw;
  camera.pitch = std::clamp(pitch, -kMaxPitch, kMaxPitch);
  if (box.isEmpty()) return camera;
  camera.focus = box.center();
  camera.distance = 1.0;
  // With the camera's axes (right, up, back) fixed by yaw and pitch, a corner c relative to the
  // focus sits at depth d - c.back. It projects inside the shrunk field of view when
  // |c.right| <= tan_x (d - c.back) and |c.up| <= tan_y (d - c.back): the smallest such d.
  const double tan_y = std::tan(0.5 * camera.fov_y) / (1.0 + 2.0 * margin);
  const double tan_x = std::tan(0.5 * camera.fov_y) * aspect / (1.0 + 2.0 * margin);
  const Eigen::Matrix4d v = camera.view();
  const Vec3 right = v.block<1, 3>(0, 0).transpose();
  const Vec3 up = v.block<1, 3>(1, 0).transpose();
  const Vec3 back = v.block<1, 3>(2, 0).transpose();
  double distance = 1e-3;
  for (int k = 0; k < 8; ++k) {
    const Vec3 c = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k)) - camera.focus;
    distance = std::max({distance, c.dot(back) + std::abs(c.dot(right)) / tan_x,
                         c.dot(back) + std::abs(c.dot(up)) / tan_y});
  }
  camera.distance = distance;
  return camera;
}

std::optional<Vec3> intersect_plane(const Ray& ray, const Vec3& point, const Vec3& normal) {
  const double along = ray.direction.dot(normal);
  if (std::abs(along) < 1e-9 * normal.norm()) return std::nullopt;
  const double t = (point - ray.origin).dot(normal) / along;
  if (t <= 0.0) return std::nullopt;
  return ray.origin + t * ray.direction;
}

std::optional<Vec3> intersect_horizontal_plane(const Ray& ray, double height) {
  return intersect_plane(ray, Vec3(0.0, height, 0.0), Vec3::UnitY());
}

}  // namespace animkit
