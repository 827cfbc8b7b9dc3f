#pragma once
// FABRIK for skeleton trees with several end effectors, after Aristidou & Lasenby
// 2011, "FABRIK: a fast, iterative solver for the inverse kinematics problem", section 5
// (multiple end effectors): sub-bases placed at the centroid of what their branches ask for.
// Joint limits are enforced inside every forward pass, orientation targets turn the effector
// joints themselves. Signature shared by every tree solver (tree_ik.h).
#include <optional>
#include <vector>

#include "animkit/core/result.h"
#include "animkit/core/types.h"
#include "animkit/kinematics/dls_tree.h"
#include "animkit/kinematics/tree_ik.h"

namespace animkit {

/// Settings of solve_fabrik_tree(); the defaults are the lab's.
struct FabrikTreeSettings {
  /// Cap on backward-forward passes; >= 1. Default 100 (the lab's).
  int max_iterations = 100;
  /// Converged when every effector joint is within this distance of its target (scene units,
  /// world space); > 0. Default 1e-4 (the lab's).
  double tolerance = 1e-4;
  /// ... and within this angle of its target orientation, when it has one (radians); > 0.
  double angular_tolerance = 1e-3;
  /// Whether a solve whose passes end short of targets that are within reach continues with
  /// damped least squares (solve_dls_tree()) from FABRIK's best pose, inside the same solve:
  /// FABRIK's passes can settle in a fixed point short of a target the limits allow (see the
  /// limits of the method below), where DLS, following the gradient with the joints at their
  /// limits taken out, goes on. The better of the two poses is returned; TreeIkResult counts
  /// the DLS iterations in `finish_iterations` (`iterations` counts the passes alone, so it
  /// stays within max_iterations). Nothing changes for a
  /// solve the passes converge (or one with a target out of reach). false: FABRIK only.
  bool finish_with_dls = true;
  /// The DLS finish's settings; its tolerance and angular_tolerance are replaced by the two
  /// above. Default: DLS's defaults (damping for skeletons in metres), 100 iterations.
  DlsSettings dls_finish{};

  /// The first problem ("tolerance must be a positive finite number, got -1"), or nothing.
  std::optional<Error> validate() const;
};

/// Caller-owned scratch of solve_fabrik_tree(): sized for a skeleton once (by resize() or by
/// the first solve), after which solves on that skeleton allocate nothing; the DLS finish's
/// workspace is sized in every solve (finish or not) for the problem's shape, so it allocates
/// again only when the effector or orientation-target count changes (as DlsWorkspace does).
/// Its contents between solves mean nothing; a reused workspace gives the same bits as a fresh
/// one.
struct FabrikTreeWorkspace {
  TreeIkScratch scratch;               ///< per-joint effector bookkeeping, best pose (tree_ik.h)
  std::vector<Vec3> desired;           ///< backward pass: where each joint is asked to go
  std::vector<double> desired_weight;  ///< the weights summed into `desired`
  DlsWorkspace dls;                    ///< the DLS finish's (FabrikTreeSettings::finish_with_dls)

  /// Sizes scratch, desired and desired_weight for `skeleton`'s joints (not `dls`, which
  /// solve_fabrik_tree() sizes when finish_with_dls is set); allocates only when the size changes.
  void resize(const Skeleton& skeleton);
};

/// FABRIK on a tree. One iteration:
///  - backward pass, effectors toward roots: an effector joint is asked to its target; every
///    other joint with effectors below it to the weighted centroid (weights: the effector
///    weights of each branch) of the positions its children's branches ask for, each at bone
///    length from that child's new position toward the joint's current position; a sub-base
///    (several such children) is the centroid of its branches (A&L 2011, section 5); below a
///    hinge with one branch under it, the bone above is asked into the hinge's plane at an
///    angle to the bone below within the hinge's range (constrained FABRIK, A&L 2011 section
///    4.1, as caliko does for hinges), so the parent is asked where the hinge can reach from;
///  - forward pass, roots outward (roots stay where they are): each joint with effectors below
///    turns so that its children's bones point at their backward-pass positions (the shortest
///    arc for one child, the weighted best-fit rotation for several), the turn is constrained
///    by the joint's limit right there, and the children are placed from the constrained
///    rotation; so bones stay rigid, the next pass starts from a pose the limits allow, and
///    subtrees without effectors turn rigidly with their parent. An effector joint with an
///    orientation target and no effectors below takes that orientation, within its limit.
/// Two refinements of the forward pass, both for limits: a hinge joint turns by the best
/// rotation about its axis (its only freedom); a joint aiming a single child also chooses its
/// twist about that bone (which moves no child) to bring the grandchildren toward their asked
/// positions, trying eight twists under limits, so that a hinge below can bend in the plane of
/// its target (only the free optimum when it meets no limit and no hinge lies below: the others
/// could only tie).
/// The solve starts by moving the pose inside the limits, stops when converged, at the cap, or
/// when iterations stop changing anything (after bending the joints above the effectors a
/// little, a few times, to leave singular or stuck poses), and returns the best pose seen.
/// On a one-branch skeleton without limits the passes place the joints as the chain's
/// solve_fabrik() does (the rotations keep the previous pose's twist, like the chain's
/// FabrikRotations::from_previous). Returns the validate_tree_ik() or settings error for
/// invalid input.
///
/// Limits of the method: the backward pass knows the hinges only (not the balls' cones and
/// twists, nor the hinge axis's own motion as the joint above turns), so with hinged knees and
/// elbows the passes can still settle in a fixed point short of a target the limits allow; and
/// several effectors pulling one rigid sub-base converge slowly, so 100 iterations reach fewer
/// jointly reachable targets than 1000 (the tests measure both). Both are what the DLS finish
/// (FabrikTreeSettings::finish_with_dls, on by default) is for; the tests measure FABRIK with
/// and without it.

Result<TreeIkResult> solve_fabrik_tree(const Skeleton& skeleton, const TreeIkProblem& problem,
                                       const FabrikTreeSettings& settings,
                                       FabrikTreeWorkspace& workspace, SkeletonPose& pose);

}  // namespace animkit
