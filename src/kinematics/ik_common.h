#pragma once
// Private helpers shared by the IK solvers: input checks and the unreachable-target pose.
#include <optional>

#include "animkit/kinematics/chain.h"
#include "animkit/kinematics/ik_types.h"

namespace animkit::detail {

/// The first problem with a solve's inputs, or nothing.
std::optional<Error> validate_ik_input(const Chain& chain, const Pose& pose, const Vec3& target,
                                       const IkOptions& options);

/// Points every bone straight from the root toward `target`: for a target beyond reach this is
/// the pose that brings the end effector nearest (at full reach on the ray root -> target).
/// Returns the result of that pose.
IkResult point_chain_at(const Chain& chain, Pose& pose, const Vec3& target,
                        const IkOptions& options);

/// True when some pose puts the end effector on the target.
bool within_reach(const Chain& chain, const Vec3& target);

}  // namespace animkit::detail
