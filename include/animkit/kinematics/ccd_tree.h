#pragma once
// Cyclic coordinate descent over skeleton trees with several end effectors: the
// lab's CCD (docs/how-it-works.md) with the shortest arc replaced, where a joint carries several
// effectors, by the weighted best-fit rotation about the joint. Joint limits are enforced at
// every joint visit. Signature shared by every tree solver (tree_ik.h).
#include <optional>

#include "animkit/core/result.h"
#include "animkit/core/types.h"
#include "animkit/kinematics/tree_ik.h"

namespace animkit {

/// Settings of solve_ccd_tree(); the defaults are the lab's.
struct CcdTreeSettings {
  /// Cap on sweeps; >= 1. Default 100 (the lab's).
  int max_iterations = 100;
  /// Converged when every effector joint is within this distance of its target (scene units,
  /// world space); > 0. Default 1e-4 (the lab's).
  double tolerance = 1e-4;
  /// ... and within this angle of its target orientation, when it has one (radians); > 0.
  double angular_tolerance = 1e-3;

  /// The first problem ("max iterations must be at least 1, got 0"), or nothing.
  std::optional<Error> validate() const;
};

/// Caller-owned scratch of solve_ccd_tree(): sized for a skeleton once (by resize() or by the
/// first solve), after which solves on that skeleton allocate nothing. Its contents between
/// solves mean nothing; a reused workspace gives the same bits as a fresh one.
struct CcdTreeWorkspace {
  TreeIkScratch scratch;  ///< per-joint effector bookkeeping and the best pose seen (tree_ik.h)

  /// Sizes the scratch for `skeleton`'s joints; allocates only when the joint count changes.
  void resize(const Skeleton& skeleton);
};

/// CCD on a tree. One sweep visits the joints from the last index to the first (children
/// before parents, so from the effectors toward the roots). A joint with effectors below it
/// turns by the rotation R about itself minimizing
///   sum_k w_k |R (e_k - p) - (t_k - p)|^2
/// over those effectors (joint position p, effector positions e_k, targets t_k, weights w_k):
/// the shortest arc for one effector (the lab's CCD), the best-fit rotation (Wahba's problem)
/// for several. The turn is constrained by the joint's limit right there and forward
/// kinematics re-run on its subtree before the sweep goes on. An effector joint with an
/// orientation target and no effectors below takes that orientation, within its limit. A
/// hinge joint turns by the best rotation about its axis instead (its only freedom). Stopping
/// and the best pose returned: as solve_fabrik_tree(). On a one-branch skeleton without limits
/// a sweep turns the joints as the chain's solve_ccd() does.
/// Returns the validate_tree_ik() or settings error for invalid input.
Result<TreeIkResult> solve_ccd_tree(const Skeleton& skeleton, const TreeIkProblem& problem,
                                    const CcdTreeSettings& settings, CcdTreeWorkspace& workspace,
                                    SkeletonPose& pose);

}  // namespace animkit
