#include "animkit/scene/collider_picking.h"

#include <cmath>

namespace animkit {

namespace {

// The ray parameter t > 0 where the ray meets triangle (a, b, c), or nothing: Moller and
// Trumbore (1997), solving origin + t d = a + u (b - a) + v (c - a) by Cramer's rule.
std::optional<double> ray_triangle(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = ray.direction.cross(e2);
  const double det = e1.dot(p);
  // Edge-on (or degenerate) triangles: the ray meets the neighbouring ones instead.
  if (std::abs(det) <= 1e-14 * e1.norm() * e2.norm()) return std::nullopt;
  const Vec3 s = ray.origin - a;
  const double u = s.dot(p) / det;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const Vec3 q = s.cross(e1);
  const double v = ray.direction.dot(q) / det;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  const double t = e2.dot(q) / det;
  if (t <= 0.0) return std::nullopt;
  return t;
}

}  // namespace

std::optional<ColliderGrab> pick_collider(const std::vector<Collider>& colliders, const Ray& ray) {
  std::optional<ColliderGrab> best;
  for (std::size_t i = 0; i < colliders.size(); ++i) {
    const Collider& c = colliders[i];
    if (c.is_half_space()) continue;
    const std::vector<Vec3>& v = c.world_vertices();
    for (const auto& t : c.model().surface.triangles) {
      const auto hit = ray_triangle(ray, v[t[0]], v[t[1]], v[t[2]]);
      if (!hit || (best && *hit >= best->distance)) continue;
      best = ColliderGrab{.collider = static_cast<int>(i),
                          .point = ray.origin + *hit * ray.direction,
                          .distance = *hit,
                          .pose = c.pose()};
    }
  }
  return best;
}

RigidPose dragged_pose(const ColliderGrab& grab, const Vec3& cursor) {
  RigidPose pose = grab.pose;
  pose.position += cursor - grab.point;
  return pose;
}

}  // namespace animkit
