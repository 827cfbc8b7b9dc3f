// Behaviour tests of `animkit cloth`'s world options: --sphere, --ground, --wind.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "../support/run_command.h"
#include "../support/temp_files.h"

namespace {

namespace fs = std::filesystem;
using animkit::testing_support::read_file;
using animkit::testing_support::run_command;

const std::string kCli = ANIMKIT_CLI_PATH;

TEST(ClothWorldCli, AClothOverASphereAndGroundWritesTheColliders) {
  const fs::path out = animkit::testing_support::fresh_dir("cloth_world_sphere");
  // The lab's cloth swings down from its pinned edge into a ball.
  const auto r = run_command(kCli +
                             " cloth --grid 8 --frames 40 --sphere 1,0.9,0,0.3 --ground 0"
                             " --no-picture --out " +
                             out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto m = nlohmann::json::parse(read_file(out / "metrics.json"));
  EXPECT_EQ(m["converged_fraction"], 1.0);
  const std::string obj = read_file(out / "colliders.obj");
  EXPECT_NE(obj.find("o sphere 1"), std::string::npos) << obj.substr(0, 200);
  EXPECT_NE(obj.find("\nf "), std::string::npos);
}

TEST(ClothWorldCli, WindRuns) {
  const auto r = run_command(kCli + " cloth --grid 8 --frames 20 --wind 3,0,0 --gust 2,0,0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

struct BadWorld {
  std::string args, message;
};

class ClothWorldCliErrors : public testing::TestWithParam<BadWorld> {};

TEST_P(ClothWorldCliErrors, SayWhatIsWrongInOneLine) {
  const auto r = run_command(kCli + " cloth --grid 4 --frames 2 " + GetParam().args);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "animkit: error: " + GetParam().message + "\n");
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ClothWorldCliErrors,
    testing::Values(
        BadWorld{"--sphere 1,2,3", "--sphere expects CX,CY,CZ,R, got '1,2,3'"},
        BadWorld{"--sphere 0,0,0,-1", "collider 'sphere 1': radius must be > 0, got -1"},
        BadWorld{"--sphere 1,1.5,0,0.5", "particle 12 starts inside collider 'sphere 1'"},
        BadWorld{"--ground 2", "particle 0 starts on or below the ground"},
        BadWorld{"--ground 0 --thickness 0", "contact thickness must be > 0 m, got 0"},
        BadWorld{"--wind 1,x,0", "--wind expects X,Y,Z in m/s, got '1,x,0'"}));

}  // namespace
