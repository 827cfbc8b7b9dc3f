#pragma once
// A motion clip as plain data: every frame's local rotations and translations of a
// skeleton, in flat frame-major arrays, so whole-clip jobs (foot locking) read and write frames
// without allocating. File formats convert to and from it (io/bvh_motion.h).
#include <vector>

#include "animkit/core/types.h"
#include "animkit/kinematics/skeleton.h"

namespace animkit {

/// A motion clip of one skeleton: every frame's local rotations and translations, frame-major.
struct SkeletalMotion {
  int joint_count = 0;  ///< joints per frame, the skeleton's joint_count(); >= 0
  /// Seconds per frame, > 0.
  double frame_time = 1.0 / 30.0;
  /// local_rotations[f * joint_count + j]: joint j's rotation relative to its parent in frame
  /// f (unit), as SkeletonPose::local_rotations.
  std::vector<Quat> local_rotations;
  /// local_translations[f * joint_count + j]: as SkeletonPose::local_translations (scene units).
  std::vector<Vec3> local_translations;

  /// Number of frames: local_rotations.size() / joint_count (0 when joint_count is 0).
  int frame_count() const {
    return joint_count > 0 ? static_cast<int>(local_rotations.size()) / joint_count : 0;
  }
  /// Copies frame f's locals into `pose` (sized for joint_count; globals untouched).
  void read_frame(int f, SkeletonPose& pose) const;
  /// Copies `pose`'s locals into frame f.
  void write_frame(int f, const SkeletonPose& pose);
};

/// An empty motion of `frames` frames for `joint_count` joints (identity rotations, zero
/// translations).
SkeletalMotion make_motion(int joint_count, int frames, double frame_time);

}  // namespace animkit
