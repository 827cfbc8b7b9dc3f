#pragma once
// Skeletons as trees: a description a user or a file reader fills in, the immutable
// model built from it once (flat arrays, parents before children), and the pose that FK fills.
// The lab's chain is a skeleton with one branch (skeleton_desc_from_chain).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "animkit/core/result.h"
#include "animkit/core/types.h"
#include "animkit/kinematics/chain.h"

namespace animkit {

/// Editable description of a skeleton of joints 0..n-1. Every vector has one entry per joint
/// (rest_rotations may be empty), and a parent always comes before its children, so one loop
/// in index order visits parents first.
struct SkeletonDesc {
  /// names[i]: non-empty and unique (files and solvers find joints by name).
  std::vector<std::string> names;
  /// parents[i]: index of joint i's parent, in [0, i); -1 for a root (several roots allowed).
  std::vector<int> parents;
  /// rest_offsets[i]: translation of joint i from its parent, in the parent's frame at rest
  /// (scene units, finite; zero allowed: e.g. a hip joint on the pelvis). For a root it is the
  /// root's world position at rest.
  std::vector<Vec3> rest_offsets;
  /// rest_rotations[i]: rotation of joint i relative to its parent at rest, a unit quaternion.
  /// Empty (the default) means identity for every joint.
  std::vector<Quat> rest_rotations;

  /// Number of joints: names.size(), which validate() requires the other vectors to match.
  int joint_count() const { return static_cast<int>(names.size()); }

  /// Appends a joint (identity rest rotation if rest_rotations is empty) and returns its index.
  int add_joint(std::string name, int parent, const Vec3& rest_offset);

  /// The first problem with this description, or nothing when it can be built.
  std::optional<Error> validate() const;
};

/// The lab's chain as a one-branch skeleton: joints "joint0".."joint<n-1>", joint i's parent
/// i - 1, the same offsets and rest rotations. Skeleton FK then equals the chain's FK.
SkeletonDesc skeleton_desc_from_chain(const ChainDesc& chain);

/// Immutable runtime model of a validated skeleton; only build_skeleton() makes one.
class Skeleton {
 public:
  /// Number of joints, >= 1.
  int joint_count() const { return static_cast<int>(parents_.size()); }
  const std::vector<std::string>& names() const { return names_; }         ///< as in SkeletonDesc
  const std::vector<int>& parents() const { return parents_; }             ///< -1 for roots
  const std::vector<Vec3>& rest_offsets() const { return rest_offsets_; }  ///< parent frame
  const std::vector<Quat>& rest_rotations() const { return rest_rotations_; }  ///< unit
  /// |rest_offsets[i]|: the bone from joint i's parent to joint i; 0 for roots.
  const std::vector<double>& bone_lengths() const { return bone_lengths_; }
  /// The children of joint i, in index order: child_list()[child_begin()[i] ..
  /// child_begin()[i + 1]) (compressed rows, so no per-joint allocation).
  const std::vector<int>& child_begin() const { return child_begin_; }
  /// Every joint's children, grouped by parent in joint order (indexed through child_begin()).
  const std::vector<int>& child_list() const { return child_list_; }
  /// Number of children of `joint` (in [0, joint_count())); 0 for a leaf.
  int child_count(int joint) const { return child_begin_[joint + 1] - child_begin_[joint]; }
  /// Joints with no children (end effectors), in index order.
  const std::vector<int>& leaves() const { return leaves_; }
  /// Joints with no parent, in index order.
  const std::vector<int>& roots() const { return roots_; }
  /// The joint named `name`, or -1.
  int find_joint(std::string_view name) const;

 private:
  friend Result<Skeleton> build_skeleton(const SkeletonDesc& desc);
  std::vector<std::string> names_;
  std::vector<int> parents_;
  std::vector<Vec3> rest_offsets_;
  std::vector<Quat> rest_rotations_;
  std::vector<double> bone_lengths_;
  std::vector<int> child_begin_, child_list_, leaves_, roots_;
};

/// Validates `desc` and builds the model; the error names the first problem found.
Result<Skeleton> build_skeleton(const SkeletonDesc& desc);

/// A configuration of a skeleton; one entry per joint in every vector.
struct SkeletonPose {
  /// Rotation of joint i relative to its parent (unit); at rest, the rest rotation.
  std::vector<Quat> local_rotations;
  /// Translation of joint i from its parent, in the parent's frame (scene units); at rest, the
  /// rest offset. A root's entry is the root translation (its world position); other joints
  /// change it only when their motion translates them (e.g. BVH position channels).
  std::vector<Vec3> local_translations;
  std::vector<Quat> global_rotations;  ///< world rotation of joint i, filled by FK
  std::vector<Vec3> global_positions;  ///< world position of joint i, filled by FK
};

/// The skeleton at rest, with forward kinematics already run.
SkeletonPose skeleton_rest_pose(const Skeleton& skeleton);
/// A pose sized for `joint_count` joints, every rotation the identity and every translation and
/// position zero: scratch that a clip's frames are read into (SkeletalMotion::read_frame).
SkeletonPose identity_pose(int joint_count);

/// Forward kinematics over the tree in one loop, parents before children (docs/how-it-works.md
/// with "i - 1" read as "parent(i)"):
///   root:  global_rotation = local_rotation,  global_position = local_translation
///   other: global_rotation[i] = global_rotation[p] * local_rotation[i]
///          global_position[i] = global_position[p] + global_rotation[p] * local_translation[i]
/// The pose must have the skeleton's size (checked by assert); nothing is allocated.
void skeleton_forward_kinematics(const Skeleton& skeleton, SkeletonPose& pose);

}  // namespace animkit
