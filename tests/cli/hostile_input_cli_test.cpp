// What a hostile tester's inputs do to `animkit cloth`: each is refused with one line naming the
// problem (exit 2), nothing left in --out, or runs and reports what it did.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "../support/run_command.h"
#include "../support/sanitizers.h"
#include "../support/temp_files.h"

namespace {

namespace fs = std::filesystem;
using animkit::testing_support::run_command;

const std::string kHostileCli = ANIMKIT_CLI_PATH;

// Writes `json` as scene.json in a fresh folder named `name` and returns its path.
fs::path hostile_scene(const std::string& name, const std::string& json) {
  const fs::path dir = animkit::testing_support::fresh_dir("hostile_" + name);
  std::ofstream(dir / "scene.json") << json;
  return dir / "scene.json";
}

// One line on stderr that starts "animkit: error: " and holds `part`, exit status 2, and no
// output folder.
void expect_refused(const animkit::testing_support::CommandOutput& r, const std::string& part,
                    const fs::path& out) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("animkit: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out)) << out;
}

// A 3 cm ball through the middle of a triangle of a 4 x 4 sheet ran, crossed, as a success.
TEST(HostileInputCli, AClothStartingPiercedByAColliderIsRefused) {
  const fs::path scene =
      hostile_scene("pea", R"({"cloth": {"grid": 4, "size": 1, "height": 1, "material": "cotton"},
                 "colliders": [{"name": "pea", "radius": 0.03, "position": [0.1, 1.0001, 0.17]}],
                 "frames": 3, "dt": 0.0333})");
  const fs::path out = scene.parent_path() / "out";
  expect_refused(run_command(kHostileCli + " cloth --scene " + scene.string() +
                             " --no-picture --out " + out.string()),
                 "collider 'pea' passes through the cloth's triangle of particles ", out);
}

TEST(HostileInputCli, AThrownColliderBeyondTheSpeedRangeIsRefused) {
  const fs::path scene =
      hostile_scene("fast", R"({"cloth": {"grid": 4, "size": 1, "height": 1, "material": "cotton"},
                  "colliders": [{"name": "ball", "radius": 0.1, "position": [0.5, 0.5, 0.5],
                                 "velocity": [1e300, 0, 0]}], "frames": 3})");
  const fs::path out = scene.parent_path() / "out";
  expect_refused(run_command(kHostileCli + " cloth --scene " + scene.string() +
                             " --no-picture --out " + out.string()),
                 "linear velocity must have each coordinate between -1e+06 and 1e+06", out);
}

TEST(HostileInputCli, ADuplicateKeyIsRefused) {
  const fs::path scene = hostile_scene("duplicate", R"({"frames": 3, "frames": 1000000})");
  const fs::path out = scene.parent_path() / "out";
  expect_refused(run_command(kHostileCli + " cloth --scene " + scene.string() +
                             " --no-picture --out " + out.string()),
                 "the key 'frames' appears twice in one object", out);
}

// --integrator auto tried the bare cloth, so a world with contact failed when VBD won.
TEST(HostileInputCli, AutoPicksAnIntegratorThatTakesContact) {
  const fs::path scene =
      hostile_scene("auto", R"({"cloth": {"grid": 4, "size": 1, "height": 0.3, "material": "cotton",
                            "pins": "none"},
                  "ground": {"height": 0}, "frames": 2})");
  const auto r = run_command(kHostileCli + " cloth --scene " + scene.string() +
                             " --integrator auto --no-picture");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find(" chose implicit-"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("vbd"), std::string::npos) << r.out;
}

// Out of memory is one line that says so (here under a 1 GiB address-space limit, with
// colliders of two million triangles); never "std::bad_alloc" or a crash. AddressSanitizer
// reserves terabytes of address space, so this runs in Release only.
TEST(HostileInputCli, RunningOutOfMemoryIsOneLine) {
  if (animkit::test_support::kUnderSanitizers) GTEST_SKIP() << "ASan needs the address space";
  std::string colliders;
  for (int i = 0; i < 390; ++i) {
    colliders += std::string(i ? "," : "") + R"({"name": "pebble )" + std::to_string(i) +
                 R"(", "radius": 0.01, "tessellation": 4, "position": [)" +
                 std::to_string(-5.0 + 0.03 * i) + ", 0.1, -3]}";
  }
  const fs::path scene = hostile_scene(
      "memory", R"({"cloth": {"grid": 4, "size": 1, "height": 1, "material": "cotton"},
                    "colliders": [)" +
                    colliders + R"(], "frames": 1})");
  const fs::path out = scene.parent_path() / "out";
  expect_refused(run_command("sh -c 'ulimit -v 1048576; " + kHostileCli + " cloth --scene " +
                             scene.string() + " --no-picture --out " + out.string() + "'"),
                 "out of memory", out);
}

}  // namespace
