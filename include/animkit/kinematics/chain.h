#pragma once
// Kinematic chain (docs/how-it-works.md): a description a user edits, the immutable model built
// from it once, and the pose that solvers change. Many poses can share one Chain.
#include <optional>
#include <span>
#include <vector>

#include "animkit/core/result.h"
#include "animkit/core/types.h"

namespace animkit {

/// Editable description of a chain of joints 0..n-1; joint 0 is the root.
struct ChainDesc {
  /// local_offsets[i]: translation of joint i from its parent, in the parent's frame at rest
  /// (scene units). local_offsets[0] is the root's world position. At least 2 joints; every
  /// offset from index 1 on is a bone and must have non-zero length.
  std::vector<Vec3> local_offsets;
  /// local_rotations[i]: rest rotation of joint i relative to its parent, a unit quaternion.
  /// Empty means identity for every joint; otherwise one per joint.
  std::vector<Quat> local_rotations;

  /// A chain whose joints rest at the given world positions, with identity rotations.
  static ChainDesc from_rest_positions(std::span<const Vec3> world_positions);

  /// The first problem with this description, or nothing when it can be built.
  std::optional<Error> validate() const;
};

/// The lab's robot arm (Y up): joints at rest at (0,1.7,0), (0,0.9,0), (0,0.5,0), (0,0.3,0),
/// (0,-0.9,0); bones 0.8, 0.4, 0.2, 1.2 (reach 2.6) hanging from a root at height 1.7.
ChainDesc lab_arm();

/// Immutable runtime model of a validated chain; only build_chain() makes one, so every Chain
/// satisfies ChainDesc::validate().
class Chain {
 public:
  const std::vector<Vec3>& local_offsets() const { return local_offsets_; }  ///< as in ChainDesc
  /// |local_offsets[i]|: the bone from joint i-1 to joint i; bone_lengths[0] = 0 (the root).
  const std::vector<double>& bone_lengths() const { return bone_lengths_; }
  const std::vector<Quat>& rest_rotations() const { return rest_rotations_; }  ///< unit, per joint
  /// Sum of bone lengths: the farthest the end effector gets from the root.
  double reach() const { return reach_; }
  /// The nearest it gets: max(0, 2 * longest bone - reach).
  double min_reach() const { return min_reach_; }
  /// Number of joints, root and end effector included; >= 2.
  int joint_count() const { return static_cast<int>(local_offsets_.size()); }
  /// The root's world position (scene units): local_offsets()[0].
  const Vec3& root_position() const { return local_offsets_[0]; }

 private:
  friend Result<Chain> build_chain(const ChainDesc& desc);
  std::vector<Vec3> local_offsets_;
  std::vector<double> bone_lengths_;
  std::vector<Quat> rest_rotations_;
  double reach_ = 0.0;
  double min_reach_ = 0.0;
};

/// Validates `desc` and builds the model; the error names the first problem found.
Result<Chain> build_chain(const ChainDesc& desc);

/// A configuration of a chain. Positions and rotations are world space ("global").
struct Pose {
  std::vector<Quat> local_rotations;   ///< rotation of joint i relative to its parent (unit)
  std::vector<Quat> global_rotations;  ///< world rotation of joint i, from forward kinematics
  std::vector<Vec3> global_positions;  ///< world position of joint i, from forward kinematics

  /// World position of the last joint, the end effector; global_positions must not be empty.
  const Vec3& end_effector() const { return global_positions.back(); }
};

/// The chain at rest, with forward kinematics already run.
Pose rest_pose(const Chain& chain);

}  // namespace animkit
