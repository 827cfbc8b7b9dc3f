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

namespace {

void describe_surface(DrawList& out, const ColliderModel& model, const std::vector<Vec3>& world,
                      const Quat& rotation, Rgba color) {
  for (const auto& tri : model.surface.triangles) {
    const Vec3 p[3] = {world[tri[0]], world[tri[1]], world[tri[2]]};
    const auto n0 = smooth_normal(model.desc.shape, model.surface.vertices[tri[0]]);
    if (!n0) {
      out.add_triangle(p[0], p[1], p[2], color, color);
      continue;
    }
    const Vec3 n[3] = {rotation * *n0,
                       rotation * *smooth_normal(model.desc.shape, model.surface.vertices[tri[1]]),
                       rotation * *smooth_normal(model.desc.shape, model.surface.vertices[tri[2]])};
    out.add_triangle(p, n, color, color);
  }
}

}  // namespace

void describe_colliders(DrawList& out, std::span<const Collider> colliders, double t,
                        const ColliderStyle& style) {
  std::vector<Vec3> world;
  for (const Collider& c : colliders) {
    if (c.is_half_space() && !style.planes) continue;
    c.world_vertices_at(t, world);
    describe_surface(out, c.model(), world, pose_at(c.model().desc.motion, t).rotation,
                     style.color);
  }
}

void describe_colliders(DrawList& out, std::span<const Collider> colliders,
                        const ColliderStyle& style) {
  for (const Collider& c : colliders) {
    if (c.is_half_space() && !style.planes) continue;
    describe_surface(out, c.model(), c.world_vertices(), c.pose().rotation, style.color);
  }
}

void describe_contact_points(DrawList& out, const std::vector<ContactPoint>& points) {
  for (const ContactPoint& p : points) {
    out.add_line(p.cloth, p.other, palette::contact_other, 1.5f);
    out.add_point(p.other, palette::contact_other, 4.0f);
    out.add_point(p.cloth, palette::contact, 5.0f);
  }
}

}  // namespace animkit
