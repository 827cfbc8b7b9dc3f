#include "animkit/kinematics/tree_ik_solver.h"

#include <array>
#include <cassert>

namespace animkit {

namespace {

struct TreeIkSolverEntry {
  TreeIkSolverKind kind;
  std::string_view name;
};

// The one list of tree solvers, in menu order; row i holds the kind whose value is i.
constexpr std::array kTreeIkSolvers{
    TreeIkSolverEntry{TreeIkSolverKind::fabrik, "fabrik"},
    TreeIkSolverEntry{TreeIkSolverKind::ccd, "ccd"},
    TreeIkSolverEntry{TreeIkSolverKind::dls, "dls"},
    TreeIkSolverEntry{TreeIkSolverKind::sdls, "sdls"},
};

constexpr std::array<TreeIkSolverKind, kTreeIkSolvers.size()> kinds() {
  std::array<TreeIkSolverKind, kTreeIkSolvers.size()> result{};
  for (std::size_t i = 0; i < kTreeIkSolvers.size(); ++i) result[i] = kTreeIkSolvers[i].kind;
  return result;
}

constexpr std::array kKinds = kinds();

constexpr bool rows_in_enum_order() {
  for (std::size_t i = 0; i < kTreeIkSolvers.size(); ++i) {
    if (static_cast<std::size_t>(kTreeIkSolvers[i].kind) != i) return false;
  }
  return true;
}
static_assert(rows_in_enum_order(), "kTreeIkSolvers rows must follow TreeIkSolverKind's order");

}  // namespace

std::string_view to_string(TreeIkSolverKind kind) {
  const auto i = static_cast<std::size_t>(kind);
  return i < kTreeIkSolvers.size() ? kTreeIkSolvers[i].name : "unknown";
}

std::optional<TreeIkSolverKind> parse_tree_ik_solver(std::string_view name) {
  for (const TreeIkSolverEntry& entry : kTreeIkSolvers) {
    if (entry.name == name) return entry.kind;
  }
  return std::nullopt;
}

std::span<const TreeIkSolverKind> all_tree_ik_solvers() {
  return kKinds;
}

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
