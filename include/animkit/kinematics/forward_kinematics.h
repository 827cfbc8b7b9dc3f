#pragma once
#include "animkit/kinematics/chain.h"

namespace animkit {

/// Forward kinematics (docs/how-it-works.md) from joint `start` on; 0 recomputes everything.
///   global_rotation[0] = local_rotation[0],  global_position[0] = local_offset[0]
///   global_rotation[i] = global_rotation[i-1] * local_rotation[i]
///   global_position[i] = global_position[i-1] + global_rotation[i-1] * local_offset[i]
/// Joints before `start` must already be up to date. The pose must have the chain's size.
void forward_kinematics(const Chain& chain, Pose& pose, int start = 0);

}  // namespace animkit
