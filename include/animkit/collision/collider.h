#pragma once
// A collider: what a cloth collides with. ColliderDesc is the editable description (shape,
// motion, friction); Collider is built once from it: an immutable, shareable model (the local
// surface mesh and its edges) plus per-instance state (the time, the pose, the surface's world
// vertices), which is all that changes as the collider moves.
#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "animkit/collision/collider_motion.h"
#include "animkit/collision/collider_shape.h"
#include "animkit/core/result.h"

namespace animkit {

/// The editable description of a collider (its shape, motion, friction and surface level), from
/// which Collider::create() builds a Collider. Plain data: check it with validate().
struct ColliderDesc {
  /// Names the collider in errors, OBJ objects and menus: non-empty, no control characters.
  std::string name = "collider";
  ColliderShape shape = SphereShape{};  ///< in the local frame; a sphere of radius 0.5 m by default
  ColliderMotion motion = ScriptedMotion{};  ///< at rest at the origin by default
  /// Coulomb friction coefficient mu between the cloth and this collider, dimensionless,
  /// finite and >= 0 (0: frictionless), default 0.3.
  double friction = 0.3;
  /// Surface level for collider_surface(), in [kMinTessellation, kMaxTessellation], default 3
  /// (a sphere of 1280 triangles, 0.9 % short of the true volume). For a sphere only what is
  /// drawn, exported and audited: contact takes the sphere itself.
  int tessellation = 3;

  /// The first problem, prefixed with the collider's name ("collider 'ball': radius must be
  /// > 0, got -1"): an empty or unprintable name, a non-positive, non-finite or huge size, an
  /// invalid mesh, a bad motion (see validate_motion), a bad friction or tessellation level.
  std::optional<Error> validate() const;
};

/// Most triangles the colliders of one scene may have together: each costs about 0.5 KB in
/// contact's structures, so this bounds them near 1 GB (a 4 MB scene file of 60,000 default
/// spheres asked for 23 GB).
inline constexpr std::size_t kMaxColliderTriangles = 2'000'000;

/// Each description valid, every name different (they name OBJ objects) and their surfaces
/// within kMaxColliderTriangles together, checked before any surface is made.
std::optional<Error> validate_colliders(const std::vector<ColliderDesc>& colliders);

/// What a Collider shares between copies and never changes.
struct ColliderModel {
  ColliderDesc desc;                      ///< the (valid) description the model was built from
  TriangleMesh surface;                   ///< collider_surface(shape), local frame
  std::vector<std::array<int, 2>> edges;  ///< surface_edges(surface)
  Eigen::AlignedBox3d surface_bounds;     ///< of the surface's vertices, local frame
};

/// A collider built from a ColliderDesc: an immutable ColliderModel, shared between copies, plus
/// this instance's time, pose and world-space surface vertices, which change as it moves.
class Collider {
 public:
  /// Validates `desc`, builds its surface and places it at time t (s, finite).
  static Result<Collider> create(const ColliderDesc& desc, double t = 0.0);

  /// The immutable model: description, local surface mesh, its edges and bounds.
  const ColliderModel& model() const { return *model_; }
  /// The same model as a shared pointer (never null), shared by every copy of this collider.
  const std::shared_ptr<const ColliderModel>& shared_model() const { return model_; }
  /// The description's name (non-empty).
  const std::string& name() const { return model_->desc.name; }
  /// The description's Coulomb friction coefficient mu, dimensionless, >= 0.
  double friction() const { return model_->desc.friction; }
  /// A plane: contact takes it as the half-space below it, not as its drawn square. Its
  /// boundary passes through pose().position with unit normal pose().rotation * +y.
  bool is_half_space() const;

  /// Moves the collider to its pose at time t (s, finite) and updates the world vertices.
  void set_time(double t);
  /// Places the collider at `pose` (finite, unit rotation) at time t, off its motion: where
  /// a user dragged it, as the solver reports it (ContactTerm::collider_pose).
  void set_pose(double t, const RigidPose& pose);
  /// The time the collider was last placed at by create(), set_time() or set_pose(), s.
  double time() const { return time_; }
  /// The pose at time(): the motion's, or the one given to set_pose().
  const RigidPose& pose() const { return pose_; }
  /// The surface's vertices at time(), world space, in the model's surface vertex order.
  const std::vector<Vec3>& world_vertices() const { return world_vertices_; }

  /// The surface's world vertices at any time t, without moving the collider (CCD needs the
  /// start and the end of a step). `out` is resized; its capacity is reused.
  void world_vertices_at(double t, std::vector<Vec3>& out) const;
  /// The velocity (world space, m/s) at time() of the collider's material point at
  /// `world_point`: what friction measures the cloth's sliding against.
  Vec3 point_velocity(const Vec3& world_point) const;
  /// Whether a world point is strictly inside the collider at time(): the analytic shape for
  /// plane, sphere, box and capsule (which holds the inscribed surface), the winding number for
  /// a mesh. See inside() in collider_inside.h for points on the surface.
  bool inside(const Vec3& world_point) const;

 private:
  explicit Collider(std::shared_ptr<const ColliderModel> model);
  std::shared_ptr<const ColliderModel> model_;
  double time_ = 0.0;
  RigidPose pose_;
  std::vector<Vec3> world_vertices_;
};

/// The first particle (positions: x, y, z per particle, world space) strictly inside any
/// collider at its current time, as "particle 17 starts inside collider 'table'".
std::optional<Error> find_particle_inside(const Eigen::VectorXd& positions,
                                          const std::vector<Collider>& colliders);

}  // namespace animkit
