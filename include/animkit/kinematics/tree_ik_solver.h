#pragma once
// The registry of IK solvers on skeleton trees (issue 12): one list that the viewer's menu,
// the CLI's choices and parametrized tests iterate. Each solver keeps its own settings and
// workspace types (fabrik_tree.h, ccd_tree.h, dls_tree.h); they share the signature in tree_ik.h.
#include <optional>
#include <span>
#include <string_view>

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

}  // namespace animkit
