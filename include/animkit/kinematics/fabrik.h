#pragma once
#include "animkit/core/types.h"
#include "animkit/kinematics/chain.h"
#include "animkit/kinematics/ik_types.h"

namespace animkit {

/// FABRIK, Aristidou & Lasenby 2011 (docs/how-it-works.md): backward and forward reaching passes
/// on joint positions until the end effector is within tolerance, then each joint's rotation is
/// recovered as the shortest arc from its rest bone direction to its new bone direction, and
/// forward kinematics is re-run, so the pose's rotations reproduce its positions. Bone twist is
/// not represented (a chain has none to keep). Same contract as solve_ccd().
Result<IkResult> solve_fabrik(const Chain& chain, Pose& pose, const Vec3& target,
                              const IkOptions& options = {});

/// FABRIK's reaching passes alone: the joint positions they find are left in
/// pose.global_positions while the rotations are untouched, so the pose is not consistent
/// until solve_fabrik() recovers them. For tests and for showing what the passes do.
Result<IkResult> fabrik_reaching_passes(const Chain& chain, Pose& pose, const Vec3& target,
                                        const IkOptions& options = {});

}  // namespace animkit
