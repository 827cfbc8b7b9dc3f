#include "animkit/kinematics/forward_kinematics.h"

#include <cassert>

namespace animkit {

void forward_kinematics(const Chain& chain, Pose& pose, int start) {
  const int n = chain.joint_count();
  assert(static_cast<int>(pose.local_rotations.size()) == n);
  assert(static_cast<int>(pose.global_rotations.size()) == n);
  assert(static_cast<int>(pose.global_positions.size()) == n);
  assert(start >= 0 && start < n);
  if (start == 0) {
    pose.global_rotations[0] = pose.local_rotations[0];
    pose.global_positions[0] = chain.local_offsets()[0];
    start = 1;
  }
  for (int i = start; i < n; ++i) {
    pose.global_rotations[i] = pose.global_rotations[i - 1] * pose.local_rotations[i];
    pose.global_positions[i] =
        pose.global_positions[i - 1] + pose.global_rotations[i - 1] * chain.local_offsets()[i];
  }
}

}  // namespace animkit
