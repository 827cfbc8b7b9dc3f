#include "animkit/io/bvh_motion.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

namespace animkit {

SkeletalMotion motion_from_bvh(const BvhClip& clip) {
  SkeletalMotion motion = make_motion(clip.joint_count(), clip.frame_count(), clip.frame_time);
  SkeletonPose pose = identity_pose(clip.joint_count());
  for (int f = 0; f < clip.frame_count(); ++f) {
    bvh_frame_to_pose(clip, f, pose);
    motion.write_frame(f, pose);
  }
  return motion;
}

void motion_to_bvh(const SkeletalMotion& motion, BvhClip& clip) {
  assert(motion.joint_count == clip.joint_count());
  assert(motion.frame_count() == clip.frame_count());
  SkeletonPose pose = identity_pose(clip.joint_count());
  for (int f = 0; f < clip.frame_count(); ++f) {
    motion.read_frame(f, pose);
    bvh_pose_to_frame(pose, clip, f);
  }
}

Result<void> scale_bvh_clip(BvhClip& clip, double factor) {
  if (!(std::isfinite(factor) && factor > 0.0))
    return fail("the scale factor must be a finite number > 0, got " + format_number(factor));
  std::vector<Eigen::Index> position_columns;
  Eigen::Index column = 0;
  for (const auto& channels : clip.channels) {
    for (BvhChannel c : channels) {
      if (c == BvhChannel::x_position || c == BvhChannel::y_position || c == BvhChannel::z_position)
        position_columns.push_back(column);
      ++column;
    }
  }
  // The largest magnitude first, so a refused factor changes nothing.
  double largest = 0.0;
  for (const Vec3& offset : clip.skeleton.rest_offsets)
    largest = std::max(largest, offset.cwiseAbs().maxCoeff());
  for (Eigen::Index c : position_columns)
    if (clip.motion.rows() > 0)
      largest = std::max(largest, clip.motion.col(c).cwiseAbs().maxCoeff());
  // Compared without overflow either way (the tests trap floating-point overflow).
  const bool beyond =
      factor > 1.0 ? largest > kBvhValueRange.max / factor : largest * factor > kBvhValueRange.max;
  if (beyond) {
    return fail("scaling by " + format_number(factor) + " puts a value beyond " +
                format_number(kBvhValueRange.max) + " (" + format_number(largest) + " times " +
                format_number(factor) + ")");
  }
  for (Vec3& offset : clip.skeleton.rest_offsets) offset *= factor;
  for (Eigen::Index c : position_columns) clip.motion.col(c) *= factor;
  return {};
}

}  // namespace animkit
