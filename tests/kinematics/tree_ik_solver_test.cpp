#include "animkit/kinematics/tree_ik_solver.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace animkit {
namespace {

TEST(TreeIkSolver, EveryKindHasAUniqueNameThatParsesBack) {
  std::set<std::string> names;
  for (const TreeIkSolverKind kind : all_tree_ik_solvers()) {
    const std::string_view name = to_string(kind);
    EXPECT_NE(name, "unknown");
    EXPECT_TRUE(names.insert(std::string(name)).second) << name;
    EXPECT_EQ(parse_tree_ik_solver(name), kind);
  }
  EXPECT_EQ(names, (std::set<std::string>{"fabrik", "ccd", "dls", "sdls"}));
}

TEST(TreeIkSolver, UnknownNamesDoNotParse) {
  EXPECT_FALSE(parse_tree_ik_solver(""));
  EXPECT_FALSE(parse_tree_ik_solver("FABRIK"));
  EXPECT_FALSE(parse_tree_ik_solver("jacobian"));
  EXPECT_EQ(all_tree_ik_solvers().front(), TreeIkSolverKind::fabrik);
}

}  // namespace
}  // namespace animkit
