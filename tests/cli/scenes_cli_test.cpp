// `animkit scenes` lists the viewer's scene registry: every entry, by name, once.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "../support/run_command.h"
#include "../support/temp_files.h"
#include "animkit/scene/scene_registry.h"

namespace scenes_cli_test {

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

TEST(ScenesCli, WritesABuiltInSceneAsAFileThatRunsAsTheScene) {
  const std::string cli = ANIMKIT_CLI_PATH;
  const auto dir = animkit::testing_support::fresh_dir("cli_scenes_write");
  const std::string file = (dir / "drape.json").string();
  const auto written = run_command(cli + " scenes --write drape-sphere " + file);
  ASSERT_EQ(written.exit_code, 0) << written.err;
  EXPECT_EQ(written.out, "wrote " + file + ": the scene drape-sphere (animkit cloth --scene " +
                             file + " runs it)\n");
  // The file runs as the scene does: the same summary line, bit for bit in the numbers printed.
  const auto from_file = run_command(cli + " cloth --scene " + file + " --frames 2 --no-picture");
  const auto built_in = run_command(cli + " cloth --scene drape-sphere --frames 2 --no-picture");
  ASSERT_EQ(from_file.exit_code, 0) << from_file.err;
  const auto energy = [](const std::string& out) { return out.substr(out.rfind(' ')); };
  EXPECT_EQ(energy(from_file.out), energy(built_in.out));

  const auto unknown = run_command(cli + " scenes --write nope " + file);
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_EQ(unknown.err,
            "animkit: error: unknown cloth scene 'nope' (expected one of: lab, drape-sphere, "
            "tablecloth, flag, spinning-sphere, fold)\n");
}

}  // namespace scenes_cli_test
