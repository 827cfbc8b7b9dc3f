#include "animkit/scene/collider_drawing.h"

#include <algorithm>
#include <optional>

namespace animkit {

namespace {

// The outward unit normal of a smooth shape at a local surface point, or nothing for shapes
// drawn flat.
std::optional<Vec3> smooth_normal(const ColliderShape& shape, const Vec3& local) {
  if (std::holds_alternative<SphereShape>(shape)) return local.normalized();
  if (const auto* capsule = std::get_if<CapsuleShape>(&shape)) {
    const double y = std::clamp(local.y(), -capsule->half_length, capsule->half_length);
    return (local - Vec3(0.0, y, 0.0)).normalized();
  }
  return std::nullopt;
}

}  // namespace

void describe_colliders(DrawList& out, const std::vector<Collider>& colliders, double t,
                        const ColliderStyle& style) {
  std::vector<Vec3> world;
  for (const Collider& c : colliders) {
    if (c.is_half_space() && !style.planes) continue;
    const ColliderModel& model = c.model();
    const Quat rotation = pose_at(model.desc.motion, t).rotation;
    c.world_vertices_at(t, world);
    for (const auto& tri : model.surface.triangles) {
      const Vec3 p[3] = {world[tri[0]], world[tri[1]], world[tri[2]]};
      const auto n0 = smooth_normal(model.desc.shape, model.surface.vertices[tri[0]]);
      if (!n0) {
        out.add_triangle(p[0], p[1], p[2], style.color, style.color);
        continue;
      }
      const Vec3 n[3] = {
          rotation * *n0,
          rotation * *smooth_normal(model.desc.shape, model.surface.vertices[tri[1]]),
          rotation * *smooth_normal(model.desc.shape, model.surface.vertices[tri[2]])};
      out.add_triangle(p, n, style.color, style.color);
    }
  }
}

}  // namespace animkit
