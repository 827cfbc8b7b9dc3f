#include "animkit/kinematics/skeletal_motion.h"

#include <cassert>
#include <cstddef>

namespace animkit {

void SkeletalMotion::read_frame(int f, SkeletonPose& pose) const {
  assert(static_cast<int>(pose.local_rotations.size()) == joint_count);
  const std::size_t base = static_cast<std::size_t>(f) * joint_count;
  for (int j = 0; j < joint_count; ++j) {
    pose.local_rotations[j] = local_rotations[base + j];
    pose.local_translations[j] = local_translations[base + j];
  }
}

void SkeletalMotion::write_frame(int f, const SkeletonPose& pose) {
  assert(static_cast<int>(pose.local_rotations.size()) == joint_count);
  const std::size_t base = static_cast<std::size_t>(f) * joint_count;
  for (int j = 0; j < joint_count; ++j) {
    local_rotations[base + j] = pose.local_rotations[j];
    local_translations[base + j] = pose.local_translations[j];
  }
}

SkeletalMotion make_motion(int joint_count, int frames, double frame_time) {
  SkeletalMotion m;
  m.joint_count = joint_count;
  m.frame_time = frame_time;
  const std::size_t n = static_cast<std::size_t>(joint_count) * frames;
  m.local_rotations.assign(n, Quat::Identity());
  m.local_translations.assign(n, Vec3::Zero());
  return m;
}

}  // namespace animkit
