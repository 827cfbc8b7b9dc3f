#pragma once
// A skeleton tree as a picture (bones as boxes, joints as spheres) and one joint's limit as
// the directions its bone may take: a hinge's arc, a ball's cone outline. Shared by the BVH
// scene and whatever else draws a character.
#include <vector>

#include "animkit/kinematics/human_limits.h"  // joint_bone_direction
#include "animkit/kinematics/joint_limits.h"
#include "animkit/kinematics/skeleton.h"
#include "animkit/scene/draw_list.h"

namespace animkit {

/// Sizes and colours of describe_skeleton()'s bones and joints.
struct SkeletonStyle {
  double bone_thickness = 0.03;  ///< box side, scene units
  double joint_radius = 0.025;   ///< sphere radius, scene units
  /// Colour of the bone boxes.
  Rgba bone = palette::bone;
  /// Colour of the joint spheres.
  Rgba joint = palette::joint;
};

/// Bones from each joint's parent to it (skipped when zero length) and a sphere per joint
/// (none on a joint sitting on its parent, which would hide it). `pose` has FK run.
void describe_skeleton(DrawList& out, const Skeleton& skeleton, const SkeletonPose& pose,
                       const SkeletonStyle& style = {});

inline constexpr Rgba kLimitColor{0.95f, 0.35f, 0.75f, 1.0f};  ///< the allowed directions
inline constexpr Rgba kBoneNowColor{1.0f, 1.0f, 1.0f, 1.0f};   ///< where the bone points now

/// The directions `joint`'s bone may take under `limit`, `radius` long from the joint, in the
/// joint's rest frame as `pose` places it (parent's world rotation x rest rotation): a hinge
/// as an arc from its min to its max angle plus its axis, a ball as its cone's rim and four
/// spokes; the bone's current direction as a white line. Nothing for a free joint.
void describe_joint_limit(DrawList& out, const Skeleton& skeleton, const SkeletonPose& pose,
                          int joint, const JointLimit& limit, double radius);

/// The points of the rim drawn for `limit` (hinge: the arc; ball: the cone's rim), as unit
/// bone directions in the joint's rest frame; `samples` + 1 points (samples below 1 count as
/// 1). Empty for a free joint.
std::vector<Vec3> limit_outline(const JointLimit& limit, const Vec3& bone, int samples);

}  // namespace animkit
