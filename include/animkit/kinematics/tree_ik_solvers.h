#pragma once
// Every tree IK solver's settings and workspace in one object, and one call that runs the solver
// a TreeIkSolverKind names: what a caller that lets its user pick the solver (the CLI's
// --solver, a viewer menu) holds, instead of a switch over four solve functions.
#include "animkit/core/result.h"
#include "animkit/kinematics/ccd_tree.h"
#include "animkit/kinematics/dls_tree.h"
#include "animkit/kinematics/fabrik_tree.h"
#include "animkit/kinematics/tree_ik.h"
#include "animkit/kinematics/tree_ik_solver.h"

namespace animkit {

/// Settings and caller-owned workspaces of every tree solver (each sized on its first solve,
/// after which solves on the same skeleton allocate nothing, as each solver promises).
struct TreeIkSolvers {
  FabrikTreeSettings fabrik;
  CcdTreeSettings ccd;
  /// DLS and SDLS share these; `dls.method` is set from the kind on every solve.
  DlsSettings dls;
  FabrikTreeWorkspace fabrik_workspace;
  CcdTreeWorkspace ccd_workspace;
  DlsWorkspace dls_workspace;

  /// Gives every solver the same iteration cap and position tolerance (scene units).
  void set_stopping(int max_iterations, double tolerance);
};

/// Runs the solver `kind` names with its settings and workspace from `solvers`: the shared
/// contract of tree_ik.h (the pose is the start and becomes the solution; errors leave it).
Result<TreeIkResult> solve_tree_ik(TreeIkSolverKind kind, const Skeleton& skeleton,
                                   const TreeIkProblem& problem, TreeIkSolvers& solvers,
                                   SkeletonPose& pose);

}  // namespace animkit
