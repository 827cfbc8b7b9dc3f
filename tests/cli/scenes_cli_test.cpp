// `animkit scenes` lists the viewer's scene registry: every entry, by name, once.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "../support/run_command.h"
#include "animkit/scene/scene_registry.h"

namespace {

using animkit::testing_support::run_command;

TEST(ScenesCli, ListsEveryRegisteredSceneWithTheCommandThatRunsIt) {
  const auto r = run_command(std::string(ANIMKIT_CLI_PATH) + " scenes");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The names that start a line, in order.
  std::vector<std::string> listed;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty() && line[0] != ' ') listed.push_back(line.substr(0, line.find(' ')));
  }
  std::vector<std::string> registered;
  for (const animkit::SceneEntry& entry : animkit::scene_entries()) {
    registered.emplace_back(entry.name);
    if (entry.kind == animkit::SceneKind::cloth) {
      EXPECT_NE(r.out.find("animkit cloth --scene " + std::string(entry.name) + "\n"),
                std::string::npos)
          << entry.name;
    }
  }
  EXPECT_EQ(listed, registered);
  EXPECT_NE(r.out.find("animkit footlock"), std::string::npos);
}

TEST(ScenesCli, TakesNoArguments) {
  const auto r = run_command(std::string(ANIMKIT_CLI_PATH) + " scenes extra");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;  // one line
}

}  // namespace
