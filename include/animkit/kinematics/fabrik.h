#pragma once
#include "animkit/core/types.h"
#include "animkit/kinematics/chain.h"
#include "animkit/kinematics/ik_types.h"

namespace animkit {

/// FABRIK, Aristidou & Lasenby 2011 (SPEC.md section 2): backward and forward reaching passes
/// on joint positions until the end effector is within tolerance, then each joint's rotation is
/// recovered as the shortest arc from its rest bone direction to its new bone direction, and
/// forward kinematics is re-run, so the pose's rotations reproduce its positions. Bone twist is
/// not represented (a chain has none to keep). Same contract as solve_ccd().
Result<IkResult> solve_fabrik(const Chain& chain, Pose& pose, const Vec3& target,
                              const IkOptions& options = {});

}  // namespace animkit
