#pragma once
// BVH clips as SkeletalMotion (kinematics/skeletal_motion.h) and back, so whole-clip jobs run
// on plain data and their result is written as the same file with new motion values.
#include "animkit/io/bvh.h"
#include "animkit/kinematics/skeletal_motion.h"

namespace animkit {

/// Every frame of `clip` as local rotations and translations (bvh_frame_to_pose per frame).
SkeletalMotion motion_from_bvh(const BvhClip& clip);

/// Writes `motion`'s frames into `clip`'s motion values (bvh_pose_to_frame per frame). The
/// motion must have the clip's joint and frame counts (asserted).
void motion_to_bvh(const SkeletalMotion& motion, BvhClip& clip);

/// Multiplies the clip's offsets and position channels by `factor` (> 0): e.g. 1 / the read
/// scale writes a clip read in metres back in its file's own units. Fails, leaving the clip
/// as it was, on a factor that is not a finite number > 0 or that would put a value beyond
/// kBvhValueRange.
Result<void> scale_bvh_clip(BvhClip& clip, double factor);

}  // namespace animkit
