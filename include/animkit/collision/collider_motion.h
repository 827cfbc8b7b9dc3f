#pragma once
// How a collider moves: its pose (where its local frame is) as a function of time. Colliders
// are kinematic: their motion is given, the cloth does not push them.
#include <optional>
#include <variant>
#include <vector>

#include "animkit/core/result.h"
#include "animkit/core/types.h"

namespace animkit {

/// A rigid placement of a local frame: world = rotation * local + position.
struct RigidPose {
  Vec3 position = Vec3::Zero();      ///< world space, m: where the local origin is
  Quat rotation = Quat::Identity();  ///< local to world, unit

  /// A point given in the local frame, in world space: rotation * local + position.
  Vec3 to_world(const Vec3& local) const { return rotation * local + position; }
  /// The inverse of to_world(): a world point in the local frame (rotation assumed unit).
  Vec3 to_local(const Vec3& world) const { return rotation.conjugate() * (world - position); }
};

/// Constant velocities from an initial pose: position(t) = p0 + v t and rotation(t) =
/// exp(w t) q0 (turning about the world axis w / |w| by |w| t, about the collider's own moving
/// origin). All zero velocities (the default) is a static collider.
struct ScriptedMotion {
  RigidPose initial = {};                ///< the pose at t = 0
  Vec3 linear_velocity = Vec3::Zero();   ///< world space, m/s, finite
  Vec3 angular_velocity = Vec3::Zero();  ///< world space, rad/s, finite
};

/// One pose of a KeyframedMotion and the time the collider reaches it.
struct Keyframe {
  double time = 0.0;                 ///< s, finite
  Vec3 position = Vec3::Zero();      ///< world space, m
  Quat rotation = Quat::Identity();  ///< local to world, unit
};

/// A pose interpolated between keyframes: position linearly, rotation by slerp along the
/// shorter arc, each at constant speed within a segment. Before the first keyframe the collider
/// rests at the first pose, after the last at the last.
struct KeyframedMotion {
  std::vector<Keyframe> keyframes;  ///< at least one, times strictly increasing
};

using ColliderMotion = std::variant<ScriptedMotion, KeyframedMotion>;

/// The first problem of a motion ("keyframe 2 is at 1 s, not after keyframe 1 at 1 s"): a
/// non-finite number, a rotation that is not a unit quaternion (|q| off 1 by more than 1e-6),
/// no keyframes, keyframe times not strictly increasing. Nothing when the motion is usable.
std::optional<Error> validate_motion(const ColliderMotion& motion);

/// The first problem of a pose alone ("rotation is not a unit quaternion (norm 2)"): a
/// non-finite position, a rotation that is not a unit quaternion (as validate_motion).
std::optional<Error> validate_pose(const RigidPose& pose);

/// Whether the motion ever changes the pose: a velocity that is not zero, or two keyframes
/// with different poses. A collider whose motion does not move is static.
bool moves(const ColliderMotion& motion);

/// Where the collider's local frame is at time t (s, finite; any sign).
RigidPose pose_at(const ColliderMotion& motion, double t);

/// The velocity (world space, m/s) at time t of the collider's material point that is at
/// `world_point` at that time: v + w x (x - c) for the frame's linear velocity v, angular
/// velocity w and origin c. A keyframed collider at a keyframe's time moves as in the segment
/// that starts there (right derivative), and is at rest before the first and from the last.
Vec3 point_velocity(const ColliderMotion& motion, double t, const Vec3& world_point);

}  // namespace animkit
