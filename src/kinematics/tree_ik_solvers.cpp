#include "animkit/kinematics/tree_ik_solvers.h"

namespace animkit {

void TreeIkSolvers::set_stopping(int max_iterations, double tolerance) {
  fabrik.max_iterations = ccd.max_iterations = dls.max_iterations = max_iterations;
  fabrik.tolerance = ccd.tolerance = dls.tolerance = tolerance;
}

Result<TreeIkResult> solve_tree_ik(TreeIkSolverKind kind, const Skeleton& skeleton,
                                   const TreeIkProblem& problem, TreeIkSolvers& solvers,
                                   SkeletonPose& pose) {
  switch (kind) {
    case TreeIkSolverKind::fabrik:
      return solve_fabrik_tree(skeleton, problem, solvers.fabrik, solvers.fabrik_workspace, pose);
    case TreeIkSolverKind::ccd:
      return solve_ccd_tree(skeleton, problem, solvers.ccd, solvers.ccd_workspace, pose);
    case TreeIkSolverKind::dls:
    case TreeIkSolverKind::sdls:
      solvers.dls.method = kind == TreeIkSolverKind::dls ? DlsMethod::damped : DlsMethod::selective;
      return solve_dls_tree(skeleton, problem, solvers.dls, solvers.dls_workspace, pose);
  }
  return fail("unknown tree IK solver");
}

}  // namespace animkit
