#pragma once
// Grabbing a collider with the mouse: which collider surface the cursor's ray meets first,
// and the pose that keeps the grabbed point under the cursor as it moves.
#include <optional>
#include <vector>

#include "animkit/collision/collider.h"
#include "animkit/scene/orbit_camera.h"

namespace animkit {

/// A collider grabbed with the mouse (pick_collider): which one, where on its surface, and its
/// pose at the press.
struct ColliderGrab {
  int collider = 0;           ///< index in the colliders picked from, >= 0
  Vec3 point = Vec3::Zero();  ///< world space, m: where the ray met the collider's surface
  double distance = 0.0;      ///< m, from the ray's origin to `point`, > 0
  RigidPose pose;             ///< the collider's pose when grabbed
};

/// The first collider surface (its world triangles as they stand) the ray meets in front of
/// its origin, or nothing. Planes are skipped: a half space is not something to carry about.
std::optional<ColliderGrab> pick_collider(const std::vector<Collider>& colliders, const Ray& ray);

/// The pose that keeps the grabbed point under the cursor (world space): the grabbed pose
/// moved by cursor - grab.point, its rotation kept.
RigidPose dragged_pose(const ColliderGrab& grab, const Vec3& cursor);

}  // namespace animkit
