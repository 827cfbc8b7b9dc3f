#include "animkit/collision/collider.h"

#include <cmath>
#include <set>
#include <utility>

#include "animkit/collision/collider_inside.h"
#include "animkit/collision/collider_surface.h"
#include "animkit/core/quote.h"
#include "animkit/core/validation.h"

namespace animkit {

namespace {

// Quiet comparisons (std::isgreater, ...): `value > 0` on a NaN raises FE_INVALID, which the
// tests trap, and a NaN is exactly what validation must report rather than trip over.
std::optional<Error> check_size(const std::string& what, double value) {
  if (!std::isgreater(value, 0.0)) return Error{what + " must be > 0, got " + format_number(value)};
  if (!std::islessequal(value, kMaxColliderSize)) {
    return Error{what + " must be at most " + format_number(kMaxColliderSize) + ", got " +
                 format_number(value)};
  }
  return std::nullopt;
}

std::optional<Error> check_shape(const PlaneShape& s) {
  return check_size("display size", s.display_size);
}
std::optional<Error> check_shape(const SphereShape& s) {
  return check_size("radius", s.radius);
}
std::optional<Error> check_shape(const BoxShape& s) {
  for (int k = 0; k < 3; ++k) {
    if (check_size("half extents", s.half_extents[k])) {
      return Error{"half extents must be > 0 and at most " + format_number(kMaxColliderSize) +
                   ", got " + to_string(s.half_extents)};
    }
  }
  return std::nullopt;
}
std::optional<Error> check_shape(const CapsuleShape& s) {
  if (auto e = check_size("radius", s.radius)) return e;
  return check_size("half length", s.half_length);
}
std::optional<Error> check_shape(const MeshShape& s) {
  // The range first: the mesh's own checks square its coordinates (triangle areas).
  const ParameterRange range{-kMaxColliderSize, kMaxColliderSize};
  for (std::size_t v = 0; v < s.mesh.vertices.size(); ++v) {
    if (is_finite(s.mesh.vertices[v]) && !range.contains(s.mesh.vertices[v]))
      return Error{range.refusal("mesh vertex " + std::to_string(v), s.mesh.vertices[v])};
  }
  return s.mesh.validate();
}

std::optional<Error> check_name(const std::string& name) {
  if (name.empty()) return Error{"a collider has an empty name"};
  for (unsigned char c : name) {
    if (c < 0x20 || c == 0x7f) {
      return Error{"collider " + quote_input(name) + " has a control character in its name"};
    }
  }
  return std::nullopt;
}

std::optional<Error> first_problem(const ColliderDesc& d) {
  if (auto e = std::visit([](const auto& s) { return check_shape(s); }, d.shape)) return e;
  if (auto e = validate_motion(d.motion)) return e;
  if (!kFrictionRange.contains(d.friction))
    return Error{kFrictionRange.refusal("friction", d.friction)};
  if (d.tessellation < kMinTessellation || d.tessellation > kMaxTessellation) {
    return Error{"tessellation must be between " + std::to_string(kMinTessellation) + " and " +
                 std::to_string(kMaxTessellation) + ", got " + std::to_string(d.tessellation)};
  }
  return std::nullopt;
}

}  // namespace

std::optional<Error> ColliderDesc::validate() const {
  if (auto e = check_name(name)) return e;
  if (auto e = first_problem(*this)) {
    return Error{"collider " + quote_input(name) + ": " + e->message};
  }
  return std::nullopt;
}

std::optional<Error> validate_colliders(const std::vector<ColliderDesc>& colliders) {
  std::set<std::string> names;
  std::size_t triangles = 0;
  for (const ColliderDesc& d : colliders) {
    if (auto e = d.validate()) return e;
    if (!names.insert(d.name).second) {
      return Error{"two colliders are named " + quote_input(d.name)};
    }
    triangles += surface_triangle_count(d.shape, d.tessellation);
  }
  if (triangles > kMaxColliderTriangles) {
    return Error{"the colliders' surfaces would have " + std::to_string(triangles) +
                 " triangles, more than the " + std::to_string(kMaxColliderTriangles) +
                 " a scene may have (lower their tessellation or use fewer colliders)"};
  }
  return std::nullopt;
}

Collider::Collider(std::shared_ptr<const ColliderModel> model) : model_(std::move(model)) {}

Result<Collider> Collider::create(const ColliderDesc& desc, double t) {
  if (auto e = desc.validate()) return fail(e->message);
  if (!std::isfinite(t)) return fail("collider time must be finite, got " + format_number(t));
  auto model = std::make_shared<ColliderModel>();
  model->desc = desc;
  model->surface = collider_surface(desc.shape, desc.tessellation);
  model->edges = surface_edges(model->surface);
  model->surface_bounds.setEmpty();
  for (const Vec3& v : model->surface.vertices) model->surface_bounds.extend(v);
  Collider collider(std::move(model));
  collider.set_time(t);
  return collider;
}

bool Collider::is_half_space() const {
  return std::holds_alternative<PlaneShape>(model_->desc.shape);
}

void Collider::set_time(double t) {
  time_ = t;
  pose_ = pose_at(model_->desc.motion, t);
  world_vertices_at(t, world_vertices_);
}

void Collider::set_pose(double t, const RigidPose& pose) {
  time_ = t;
  pose_ = pose;
  const auto& local = model_->surface.vertices;
  world_vertices_.resize(local.size());
  for (std::size_t i = 0; i < local.size(); ++i) world_vertices_[i] = pose.to_world(local[i]);
}

void Collider::world_vertices_at(double t, std::vector<Vec3>& out) const {
  const RigidPose pose = pose_at(model_->desc.motion, t);
  const auto& local = model_->surface.vertices;
  out.resize(local.size());
  for (std::size_t i = 0; i < local.size(); ++i) out[i] = pose.to_world(local[i]);
}

Vec3 Collider::point_velocity(const Vec3& world_point) const {
  return animkit::point_velocity(model_->desc.motion, time_, world_point);
}

bool Collider::inside(const Vec3& world_point) const {
  const Vec3 local = pose_.to_local(world_point);
  // A closed mesh's winding number is 0 outside its bounding box: skip the O(triangles) sum.
  if (std::holds_alternative<MeshShape>(model_->desc.shape) &&
      !model_->surface_bounds.contains(local)) {
    return false;
  }
  return animkit::inside(model_->desc.shape, local);
}

std::optional<Error> find_particle_inside(const Eigen::VectorXd& positions,
                                          const std::vector<Collider>& colliders) {
  const Eigen::Index particles = positions.size() / 3;
  for (Eigen::Index i = 0; i < particles; ++i) {
    const Vec3 p = positions.segment<3>(3 * i);
    for (const Collider& c : colliders) {
      if (c.inside(p)) {
        return Error{"particle " + std::to_string(i) + " starts inside collider " +
                     quote_input(c.name())};
      }
    }
  }
  return std::nullopt;
}

}  // namespace animkit
