#include "animkit/scene/skeleton_drawing.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace animkit {

namespace {

// A unit vector perpendicular to the unit `axis`.
Vec3 perpendicular(const Vec3& axis) {
  const Vec3 other = std::abs(axis.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return axis.cross(other).normalized();
}

}  // namespace

void describe_skeleton(DrawList& out, const Skeleton& skeleton, const SkeletonPose& pose,
                       const SkeletonStyle& style) {
  for (int j = 0; j < skeleton.joint_count(); ++j) {
    const int parent = skeleton.parents()[j];
    const bool on_parent = parent >= 0 && skeleton.bone_lengths()[j] < 1e-9;
    if (parent >= 0 && !on_parent) {
      out.add_bone_box(pose.global_positions[parent], pose.global_positions[j],
                       style.bone_thickness, style.bone);
    }
    if (!on_parent)
      out.add_sphere(pose.global_positions[j], style.joint_radius, style.joint, 10, 6);
  }
}

std::vector<Vec3> limit_outline(const JointLimit& limit, const Vec3& bone, int samples) {
  samples = std::max(samples, 1);  // the formulas below divide by it
  std::vector<Vec3> rim;
  if (const auto* hinge = std::get_if<HingeLimit>(&limit)) {
    for (int k = 0; k <= samples; ++k) {
      const double angle = hinge->min_angle + (hinge->max_angle - hinge->min_angle) * k / samples;
      rim.push_back(Eigen::AngleAxisd(angle, hinge->axis) * bone);
    }
  } else if (const auto* ball = std::get_if<BallLimit>(&limit)) {
    // The rim: swings whose rotation vector lies on the limit's ellipse (a circle when
    // swing_angle_2 is unset), applied to the twist axis.
    const Vec3 u = ball->swing_angle_2 ? ball->swing_axis : perpendicular(ball->twist_axis);
    const Vec3 v = ball->twist_axis.cross(u);
    const double b = ball->swing_angle_2.value_or(ball->swing_angle);
    for (int k = 0; k <= samples; ++k) {
      const double phi = 2.0 * std::numbers::pi * k / samples;
      const Vec3 r = ball->swing_angle * std::cos(phi) * u + b * std::sin(phi) * v;
      const double angle = r.norm();
      rim.push_back(angle > 0.0 ? Vec3(Eigen::AngleAxisd(angle, r / angle) * ball->twist_axis)
                                : ball->twist_axis);
    }
  }
  return rim;
}

void describe_joint_limit(DrawList& out, const Skeleton& skeleton, const SkeletonPose& pose,
                          int joint, const JointLimit& limit, double radius) {
  if (std::holds_alternative<FreeJoint>(limit)) return;
  const int parent = skeleton.parents()[joint];
  const Quat parent_rotation = parent >= 0 ? pose.global_rotations[parent] : Quat::Identity();
  const Quat rest_frame = parent_rotation * skeleton.rest_rotations()[joint];
  const Vec3& at = pose.global_positions[joint];
  const Vec3 bone = joint_bone_direction(skeleton, joint);
  constexpr int kSamples = 48;
  std::vector<Vec3> rim = limit_outline(limit, bone, kSamples);
  for (Vec3& p : rim) p = at + radius * (rest_frame * p);
  out.add_polyline(rim, kLimitColor, 2.5f);
  if (const auto* hinge = std::get_if<HingeLimit>(&limit)) {
    out.add_line(at, rim.front(), kLimitColor, 1.5f);
    out.add_line(at, rim.back(), kLimitColor, 1.5f);
    const Vec3 axis = rest_frame * hinge->axis;
    out.add_line(at - 0.4 * radius * axis, at + 0.4 * radius * axis, kLimitColor, 1.5f);
  } else {
    for (int k = 0; k < 4; ++k) out.add_line(at, rim[k * kSamples / 4], kLimitColor, 1.0f);
  }
  out.add_line(at, at + radius * (pose.global_rotations[joint] * bone), kBoneNowColor, 2.5f);
}

}  // namespace animkit
