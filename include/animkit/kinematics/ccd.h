#pragma once
#include "animkit/core/types.h"
#include "animkit/kinematics/chain.h"
#include "animkit/kinematics/ik_types.h"

namespace animkit {

/// Cyclic coordinate descent (docs/how-it-works.md). One iteration visits the joints from the one
/// nearest the end effector back to the root; each turns by the shortest arc taking
/// (joint -> end effector) onto (joint -> target), as if forward kinematics were re-run from
/// it (the sweep carries only what later joints read; see ccd.cpp).
/// Starts from `pose` (warm start) and leaves the solution in it. The pose must be up to date,
/// i.e. as rest_pose(), forward_kinematics() or any solver leaves it (solvers do not re-run
/// FK first: it would cost a fifth of a warm-started FABRIK solve). Targets beyond the chain's
/// reach straighten the chain toward the target and report reachable = false.
/// Errors: NaN/inf target, a pose that does not fit the chain, invalid options.
Result<IkResult> solve_ccd(const Chain& chain, Pose& pose, const Vec3& target,
                           const IkOptions& options = {});

}  // namespace animkit
