#pragma once
// Private helpers shared by the IK solvers: input checks and the unreachable-target pose.
#include <optional>

#include "animkit/kinematics/chain.h"
#include "animkit/kinematics/ik_types.h"

namespace animkit::detail {

/// The part of a solve every solver shares, run before iterating: the result when the solve
/// ends here (invalid input, or a target beyond reach, answered with the straight chain), or
/// nothing when the solver should iterate.
std::optional<Result<IkResult>> settle_without_iterating(const Chain& chain, Pose& pose,
                                                         const Vec3& target,
                                                         const IkOptions& options);

/// Points every bone straight from the root toward `target`: for a target beyond reach this is
/// the pose that brings the end effector nearest (at full reach on the ray root -> target).
/// Returns the result of that pose.
IkResult point_chain_at(const Chain& chain, Pose& pose, const Vec3& target,
                        const IkOptions& options);

/// An iteration that shrinks the error by less than this fraction has stalled. Both solvers
/// stall only in singular poses: the chain lies on the line through the target with every
/// joint direction already parallel (e.g. the lab's triangle starts at (0,0,0), straight
/// below the root of the hanging arm, so CCD finds no joint to turn and FABRIK slides along
/// the line).
constexpr double kStallRatio = 1e-6;

/// The small world rotation (0.2 rad about an axis perpendicular to root -> target) that
/// bends a stalled chain out of its singular line, after which the solver makes progress.
Quat stall_kick(const Chain& chain, const Pose& pose, const Vec3& target);

/// True when some pose puts the end effector on the target.
bool within_reach(const Chain& chain, const Vec3& target);

}  // namespace animkit::detail
