#pragma once
// The registry of IK solvers on skeleton trees: one list that the viewer's menu,
// the CLI's choices and parametrized tests iterate, and one call that runs the solver a kind
// names (what a caller that lets its user pick the solver holds, instead of a switch over four
// solve functions). Each solver keeps its own settings and workspace types (fabrik_tree.h,
// ccd_tree.h, dls_tree.h); they share the signature in tree_ik.h.
#include <optional>
#include <span>
#include <string_view>

#include "animkit/core/result.h"
#include "animkit/kinematics/ccd_tree.h"
#include "animkit/kinematics/dls_tree.h"
#include "animkit/kinematics/fabrik_tree.h"
#include "animkit/kinematics/tree_ik.h"

namespace animkit {

/// A tree IK solver. Adding one: a value here and a row in the table of tree_ik_solver.cpp.
enum class TreeIkSolverKind {
  fabrik,  ///< solve_fabrik_tree(): FABRIK with sub-bases (Aristidou & Lasenby 2011)
  ccd,     ///< solve_ccd_tree(): cyclic coordinate descent with best-fit rotations
  dls,     ///< solve_dls_tree() with DlsMethod::damped: damped least squares
  sdls,    ///< solve_dls_tree() with DlsMethod::selective (Buss & Kim 2005)
};

/// The solver's name: "fabrik", "ccd", "dls", "sdls".
std::string_view to_string(TreeIkSolverKind kind);
/// The solver named `name` (as to_string() spells it), or nothing.
std::optional<TreeIkSolverKind> parse_tree_ik_solver(std::string_view name);
/// Every tree solver, in menu order.
std::span<const TreeIkSolverKind> all_tree_ik_solvers();

/// Settings and caller-owned workspaces of every tree solver (each sized on its first solve,
/// after which solves on the same skeleton allocate nothing, as each solver promises).
struct TreeIkSolvers {
  FabrikTreeSettings fabrik;  ///< settings of solve_fabrik_tree() (TreeIkSolverKind::fabrik)
  CcdTreeSettings ccd;        ///< settings of solve_ccd_tree() (TreeIkSolverKind::ccd)
  /// DLS and SDLS share these; `dls.method` is set from the kind on every solve.
  DlsSettings dls;
  FabrikTreeWorkspace fabrik_workspace;  ///< scratch of solve_fabrik_tree()
  CcdTreeWorkspace ccd_workspace;        ///< scratch of solve_ccd_tree()
  DlsWorkspace dls_workspace;            ///< scratch of solve_dls_tree(), for DLS and SDLS alike

  /// Gives every solver the same iteration cap and position tolerance (scene units).
  void set_stopping(int max_iterations, double tolerance);
};

/// Runs the solver `kind` names with its settings and workspace from `solvers`: the shared
/// contract of tree_ik.h (the pose is the start and becomes the solution; errors leave it).
Result<TreeIkResult> solve_tree_ik(TreeIkSolverKind kind, const Skeleton& skeleton,
                                   const TreeIkProblem& problem, TreeIkSolvers& solvers,
                                   SkeletonPose& pose);

}  // namespace animkit
