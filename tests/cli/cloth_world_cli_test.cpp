// Behaviour tests of `animkit cloth`'s world options: --sphere, --ground, --wind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "../support/run_command.h"
#include "../support/temp_files.h"

namespace cloth_world_cli_test {

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

TEST(ClothWorldCli, BoxesAndCapsulesComeFromTheCommandLineAsSpheresDo) {
  const fs::path out = animkit::testing_support::fresh_dir("cloth_world_box");
  // The lab's cloth swings down onto a box and a capsule lying along z.
  const auto r = run_command(kCli +
                             " cloth --grid 8 --frames 20 --box 0.6,0.9,0,0.2,0.1,0.2"
                             " --capsule 1.4,0.9,0,0.1,0.3,0,0,1 --no-picture --out " +
                             out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string obj = read_file(out / "colliders.obj");
  EXPECT_NE(obj.find("o box 1"), std::string::npos) << obj.substr(0, 200);
  EXPECT_NE(obj.find("o capsule 1"), std::string::npos);
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
        BadWorld{"--ground 0 --thickness 0",
                 "contact thickness must be > 0 m and at most 1e+06 m, got 0"},
        BadWorld{
            "--ground 0 --thickness 10",
            "contact thickness 10 m is more than the cloth's mean edge length, 0.559173 m: the "
            "sheet's neighbouring triangles would repel each other"},
        BadWorld{"--sphere 1e300,0,0,1",
                 "collider 'sphere 1': initial position must have each coordinate between "
                 "-1e+06 and 1e+06, got (1e+300, 0, 0)"},
        BadWorld{"--ground 0 --friction 1e300",
                 "the ground's friction must be between 0 and 10, got 1e+300"},
        BadWorld{"--wind 1e300,0,0",
                 "wind velocity (m/s) must have each coordinate between -1e+06 and 1e+06, got "
                 "(1e+300, 0, 0)"},
        BadWorld{"--thickness 0.01",
                 "--thickness applies to contact: give a collider (--sphere, --box, --capsule) "
                 "or --ground too"},
        BadWorld{"--friction 0.5",
                 "--friction applies to contact: give a collider (--sphere, --box, --capsule) or "
                 "--ground too"},
        BadWorld{"--box 1,0,0,1,1", "--box expects CX,CY,CZ,HX,HY,HZ, got '1,0,0,1,1'"},
        BadWorld{
            "--box 1,0,0,0.1,-1,0.1",
            "collider 'box 1': half extents must be > 0 and at most 1e+06, got (0.1, -1, 0.1)"},
        BadWorld{"--capsule 1,0,0,0.1,0.2,0,0,0",
                 "--capsule's direction AX,AY,AZ must be a non-zero vector, got "
                 "'1,0,0,0.1,0.2,0,0,0'"},
        BadWorld{"--capsule 1,0,0,0.1",
                 "--capsule expects CX,CY,CZ,R,H or CX,CY,CZ,R,H,AX,AY,AZ, got '1,0,0,0.1'"},
        BadWorld{"--gust 1,0,0",
                 "--gust adds gusts to a wind: give --wind too (--wind 0,0,0 for gusts alone)"},
        BadWorld{"--scene ''", "--scene needs a built-in scene's name or a .json file, got ''"},
        BadWorld{"--wind 1,x,0", "--wind expects X,Y,Z in m/s, got '1,x,0'"}));

TEST(ClothWorldCli, RunsABuiltInSceneAndReportsItsContacts) {
  const fs::path out = animkit::testing_support::fresh_dir("cloth_scene_builtin");
  const auto r = run_command(kCli + " cloth --scene drape-sphere --frames 3 --no-picture --out " +
                             out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto m = nlohmann::json::parse(read_file(out / "metrics.json"));
  EXPECT_EQ(m["scene"], "drape-sphere");
  EXPECT_EQ(m["frames"], 3);  // --frames replaces the scene's own
  EXPECT_EQ(m["options"]["material"], "cotton");
  EXPECT_EQ(m["integrator"], "implicit-multigrid");
  ASSERT_TRUE(m.contains("contact"));
  EXPECT_GT(m["contact"]["min_distance"].get<double>(), 0.0);
  EXPECT_TRUE(m["steps"][0].contains("contact_pairs"));
  EXPECT_TRUE(m["steps"][0].contains("step_bound_min"));
  EXPECT_NE(read_file(out / "colliders.obj").find("o ball"), std::string::npos);
}

TEST(ClothWorldCli, RunsASceneFile) {
  const fs::path dir = animkit::testing_support::fresh_dir("cloth_scene_file");
  {
    std::ofstream scene(dir / "scene.json");
    scene << R"({"cloth": {"grid": 6, "material": "silk", "size": 0.5, "height": 0.5,
                           "pins": "none"},
                 "ground": {"height": 0.2}, "dt": 0.02, "frames": 4})";
  }
  const auto r = run_command(kCli + " cloth --scene " + (dir / "scene.json").string() +
                             " --no-picture --out " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto m = nlohmann::json::parse(read_file(dir / "out" / "metrics.json"));
  EXPECT_EQ(m["frames"], 4);
  EXPECT_EQ(m["options"]["dt"], 0.02);
  EXPECT_EQ(m["particles"], 49);
}

TEST(ClothWorldCli, SceneErrorsSayWhatIsWrong) {
  const fs::path dir = animkit::testing_support::fresh_dir("cloth_scene_errors");
  std::ofstream(dir / "bad.json") << R"({"colliders": [{"shape": "cube"}]})";
  const struct {
    std::string args, message;
  } cases[] = {
      {"--scene nope",
       "unknown scene 'nope' (expected a .json file or one of: lab, drape-sphere, tablecloth, "
       "flag, spinning-sphere, fold)"},
      {"--scene flag --sphere 0,0,0,1",
       "--sphere describes the cloth or its world, which --scene gives whole"},
      {"--scene " + (dir / "bad.json").string(),
       (dir / "bad.json").string() +
           ": colliders[0].shape: expected sphere, box, capsule or mesh, got 'cube'"},
      {"--scene " + (dir / "none.json").string(), (dir / "none.json").string() + ": no such file"},
  };
  for (const auto& c : cases) {
    const auto r = run_command(kCli + " cloth " + c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args;
    EXPECT_EQ(r.err, "animkit: error: " + c.message + "\n");
  }
}

}  // namespace cloth_world_cli_test
