#include "animkit/io/bvh_motion.h"

#include <cassert>

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

void scale_bvh_clip(BvhClip& clip, double factor) {
  assert(factor > 0.0);
  for (Vec3& offset : clip.skeleton.rest_offsets) offset *= factor;
  int column = 0;
  for (const auto& channels : clip.channels) {
    for (BvhChannel c : channels) {
      const bool position =
          c == BvhChannel::x_position || c == BvhChannel::y_position || c == BvhChannel::z_position;
      if (position) clip.motion.col(column) *= factor;
      ++column;
    }
  }
}

}  // namespace animkit
