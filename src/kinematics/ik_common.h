#pragma once
// Private helpers shared by the IK solvers: input checks and the unreachable-target pose.
#include <optional>
#include <vector>

#include "animkit/kinematics/chain.h"
#include "animkit/kinematics/ik_types.h"

namespace animkit::detail {

/// The part of a solve every solver shares, run before iterating: the result when the solve
/// ends here, or nothing when the solver should iterate. It ends here for invalid input, and
/// for a target at least (reach - tolerance) from the root, answered with the straight chain:
/// beyond reach that is the nearest pose, and just inside it is within tolerance, where both
/// solvers would otherwise crawl (the chain's Jacobian is singular at full extension).
std::optional<Result<IkResult>> settle_without_iterating(const Chain& chain, Pose& pose,
                                                         const Vec3& target,
                                                         const IkOptions& options);

/// Points every bone straight from the root toward `target`: for a target beyond reach this is
/// the pose that brings the end effector nearest (at full reach on the ray root -> target).
/// Returns the result of that pose.
IkResult point_chain_at(const Chain& chain, Pose& pose, const Vec3& target,
                        const IkOptions& options);

/// An iteration that shrinks the error by less than this fraction has stalled. That happens in
/// two ways. In a singular pose the chain lies on the line through the target with every
/// joint direction already parallel (the lab's triangle starts at (0,0,0), straight below the
/// root of the hanging arm): CCD finds no joint to turn and FABRIK slides along the line; a
/// kick (below) gets it going. Otherwise the error has reached rounding level (a tolerance
/// below what double precision resolves) and the solver stops.
constexpr double kStallRatio = 1e-6;

/// Whether a stalled solve is in a singular pose: every joint on the line through the root
/// and the target (to 1e-9 of the reach).
bool on_singular_line(const Chain& chain, const std::vector<Vec3>& positions, const Vec3& target);

/// The small world rotation (0.2 rad about an axis perpendicular to root -> target) that
/// bends a stalled chain out of its singular line, after which the solver makes progress.
Quat stall_kick(const Chain& chain, const Pose& pose, const Vec3& target);

/// For a solve that did not converge: if the straight chain pointing at the target ends
/// nearer to it than the solver's pose (targets near full reach, where both solvers crawl),
/// switch to the straight chain. Keeps `result.iterations`.
void prefer_straight_if_nearer(const Chain& chain, Pose& pose, const Vec3& target,
                               const IkOptions& options, IkResult& result);

/// True when some pose puts the end effector on the target.
bool within_reach(const Chain& chain, const Vec3& target);

}  // namespace animkit::detail
