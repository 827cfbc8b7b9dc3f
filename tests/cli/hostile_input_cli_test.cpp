// What a hostile tester's inputs do to `animkit cloth`: each is refused with one line naming the
// problem (exit 2), nothing left in --out, or runs and reports what it did.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "../support/intersection_audit.h"
#include "../support/run_command.h"
#include "../support/sanitizers.h"
#include "../support/temp_files.h"
#include "animkit/io/obj_mesh.h"
#include "animkit/io/point_cache.h"

namespace hostile_input_cli_test {

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

// `animkit cloth --scene` on `json` (written by hostile_scene) with `options`, refused as above.
void expect_scene_refused(const std::string& name, const std::string& json,
                          const std::string& options, const std::string& part) {
  const fs::path scene = hostile_scene(name, json);
  const fs::path out = scene.parent_path() / "out";
  expect_refused(run_command(kHostileCli + " cloth --scene " + scene.string() + " " + options +
                             " --out " + out.string()),
                 part, out);
}

// A 3 cm ball through the middle of a triangle of a 4 x 4 sheet ran, crossed, as a success.
TEST(HostileInputCli, AClothStartingPiercedByAColliderIsRefused) {
  expect_scene_refused(
      "pea", R"({"cloth": {"grid": 4, "size": 1, "height": 1, "material": "cotton"},
                 "colliders": [{"name": "pea", "radius": 0.03, "position": [0.1, 1.0001, 0.17]}],
                 "frames": 3, "dt": 0.0333})",
      "--no-picture", "collider 'pea' passes through the cloth's triangle of particles ");
}

TEST(HostileInputCli, AThrownColliderBeyondTheSpeedRangeIsRefused) {
  expect_scene_refused(
      "fast", R"({"cloth": {"grid": 4, "size": 1, "height": 1, "material": "cotton"},
                  "colliders": [{"name": "ball", "radius": 0.1, "position": [0.5, 0.5, 0.5],
                                 "velocity": [1e300, 0, 0]}], "frames": 3})",
      "--no-picture", "linear velocity must have each coordinate between -1e+06 and 1e+06");
}

// --friction beside --scene was silently ignored (the scene gives the world whole).
TEST(HostileInputCli, AWorldOptionBesideASceneIsRefused) {
  expect_scene_refused("friction", R"({"ground": {}, "frames": 2})", "--friction 0.5",
                       "--friction describes the cloth or its world, which --scene gives whole");
}

TEST(HostileInputCli, ADuplicateKeyIsRefused) {
  expect_scene_refused("duplicate", R"({"frames": 3, "frames": 1000000})", "--no-picture",
                       "the key 'frames' appears twice in one object");
}

// --integrator auto tried the bare cloth, so a world with contact failed when VBD won; a
// scene file could not ask for "auto" at all.
TEST(HostileInputCli, AutoPicksAnIntegratorThatTakesContact) {
  const std::string world = R"({"cloth": {"grid": 4, "size": 1, "height": 0.3,
                                          "material": "cotton", "pins": "none"},
                                "ground": {"height": 0}, "frames": 2)";
  const fs::path plain = hostile_scene("auto", world + "}");
  const fs::path asking =
      hostile_scene("auto_scene", world + R"(, "solver": {"integrator": "auto"}})");
  for (const std::string& command :
       {" cloth --scene " + plain.string() + " --integrator auto --no-picture",
        " cloth --scene " + asking.string() + " --no-picture"}) {
    const auto r = run_command(kHostileCli + command);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find(" chose implicit-"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("vbd"), std::string::npos) << r.out;
  }
}

// Out of memory is one line that says so (here under a 1 GiB address-space limit, with
// colliders of two million triangles: boxes, as contact takes a sphere as itself, not as its
// triangles); never "std::bad_alloc" or a crash. AddressSanitizer reserves terabytes of address
// space, so this runs in Release only.
TEST(HostileInputCli, RunningOutOfMemoryIsOneLine) {
  if (animkit::test_support::kUnderSanitizers) GTEST_SKIP() << "ASan needs the address space";
  std::string colliders;
  for (int i = 0; i < 650; ++i) {  // 650 boxes of 3,072 triangles
    colliders += std::string(i ? "," : "") + R"({"name": "pebble )" + std::to_string(i) +
                 R"(", "shape": "box", "half_extents": [0.01, 0.01, 0.01], "tessellation": 4,
                     "position": [)" +
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

// A mesh's error named neither the file nor the option it came from.
TEST(HostileInputCli, AMeshErrorNamesItsFile) {
  const fs::path dir = animkit::testing_support::fresh_dir("hostile_fin");
  std::ofstream(dir / "fin.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n"
                                    "f 1 2 3\nf 2 1 4\nf 1 2 5\n";
  const auto r = run_command(kHostileCli + " cloth --mesh " + (dir / "fin.obj").string() +
                             " --frames 1 --out " + (dir / "out").string());
  expect_refused(
      r,
      (dir / "fin.obj").string() + ": mesh edge between vertices 0 and 1 is shared by 3 triangles",
      dir / "out");
}

// Local/global iterations stop at their cap far from 1e-12 on denim: results, with a warning.
TEST(HostileInputCli, StepsShortOfTheToleranceAreWarnedAbout) {
  const auto r = run_command(kHostileCli +
                             " cloth --grid 8 --material denim --integrator local-global "
                             "--tolerance 1e-12 --frames 2 --dt 0.0333");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err,
            "animkit: warning: 2 of 2 steps stopped short of the tolerance (the solver's "
            "iteration cap)\n");
}

// Property: random small scenes (colliders still or moving, pins, ground, self-contact, wind,
// friction) either are refused in one line with nothing written, or run and leave whole
// results: no temporary, no non-finite number, no frame where the cloth passes through a
// collider, the ground or (with self-contact) itself by CGAL's exact audit, and a step called
// converged met its gradient tolerance, the others counted in the warning.
class RandomScene {
 public:
  explicit RandomScene(std::uint32_t seed) : rng_(seed) {}

  nlohmann::json make() {
    const double size = uniform(0.5, 1.5), height = uniform(0.4, 1.2);
    nlohmann::json scene = {{"cloth",
                             {{"grid", pick({3, 4, 5, 6})},
                              {"size", size},
                              {"height", height},
                              {"material", pick<std::string>({"cotton", "silk", "denim"})},
                              {"pins", pick<std::string>({"corners", "edge", "none"})}}},
                            {"frames", 5},
                            {"dt", pick({1.0 / 60.0, 1.0 / 30.0})}};
    self_contact_ = chance(0.5);
    scene["contact"] = {{"self_contact", self_contact_}};
    if (chance(0.7)) scene["ground"] = {{"height", 0.0}, {"friction", uniform(0.0, 0.6)}};
    const int colliders = pick({0, 1, 1, 2});
    for (int i = 0; i < colliders; ++i) {
      nlohmann::json c = {
          {"name", "c" + std::to_string(i)},
          {"position", {uniform(0.0, size), uniform(0.1, height), uniform(-0.5, 0.5) * size}},
          {"friction", uniform(0.0, 0.6)}};
      const std::string shape = pick<std::string>({"sphere", "box", "capsule"});
      c["shape"] = shape;
      if (shape == "box") {
        c["half_extents"] = {uniform(0.05, 0.3), uniform(0.05, 0.3), uniform(0.05, 0.3)};
      } else {
        c["radius"] = uniform(0.05, 0.3);
        if (shape == "capsule") c["half_length"] = uniform(0.05, 0.3);
      }
      if (chance(0.4)) c["velocity"] = {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
      scene["colliders"].push_back(c);
    }
    if (chance(0.3)) scene["wind"] = {{"velocity", {uniform(-5, 5), 0.0, uniform(-5, 5)}}};
    return scene;
  }
  bool self_contact() const { return self_contact_; }

 private:
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }
  template <class T>
  T pick(std::initializer_list<T> options) {
    std::uniform_int_distribution<std::size_t> index(0, options.size() - 1);
    return *(options.begin() + index(rng_));
  }

  std::mt19937 rng_;
  bool self_contact_ = true;
};

// Frame k of a point cache as a mesh's vertices.
std::vector<animkit::Vec3> cache_frame(const animkit::PointCache& cache, std::size_t k) {
  std::vector<animkit::Vec3> points(static_cast<std::size_t>(cache.points));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const float* p = &cache.frames[k][3 * i];
    points[i] = animkit::Vec3(p[0], p[1], p[2]);
  }
  return points;
}

TEST(HostileInputCli, RandomScenesAreRefusedCleanlyOrRunWhole) {
  const int scenes = animkit::test_support::trials_for_this_build(30);
  int ran = 0, refused = 0;
  for (int trial = 0; trial < scenes; ++trial) {
    RandomScene random(20261127u + static_cast<std::uint32_t>(trial));
    const nlohmann::json scene = random.make();
    const fs::path file = hostile_scene("random_" + std::to_string(trial), scene.dump());
    const fs::path out = file.parent_path() / "out";
    const auto r = run_command(kHostileCli + " cloth --scene " + file.string() +
                               " --no-picture --out " + out.string());
    SCOPED_TRACE(scene.dump());
    // Nothing but the scene and the results: no staging folder, no temporary.
    for (const auto& entry : fs::recursive_directory_iterator(file.parent_path())) {
      const std::string name = entry.path().filename().string();
      EXPECT_TRUE(name == ".animkit-outputs" || name.find(".animkit-") == std::string::npos)
          << entry.path();
      EXPECT_FALSE(name.ends_with(".tmp")) << entry.path();
    }
    if (r.exit_code == 2) {
      expect_refused(r, "", out);
      ++refused;
      continue;
    }
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ++ran;
    const std::string text = animkit::testing_support::read_file(out / "metrics.json");
    EXPECT_EQ(text.find("null"), std::string::npos) << "a non-finite number in metrics.json";
    const auto metrics = nlohmann::json::parse(text);
    int unconverged = 0;
    for (const auto& step : metrics["steps"]) {
      if (!step["converged"].get<bool>()) {
        ++unconverged;
      } else {  // by the gradient or by the velocity stop (the fast settings')
        EXPECT_TRUE(step["gradient_norm_end"].get<double>() <=
                        step["gradient_tolerance"].get<double>() ||
                    step["newton_speed_end"].get<double>() <= step["speed_tolerance"].get<double>())
            << step;
      }
    }
    EXPECT_EQ(r.err.empty(), unconverged == 0) << r.err;

    const auto cloth = animkit::read_pc2(out / "cloth.pc2");
    ASSERT_TRUE(cloth) << cloth.error().message;
    auto sheet = animkit::read_obj_mesh(out / "cloth.obj");
    ASSERT_TRUE(sheet) << sheet.error().message;
    std::optional<animkit::TriangleMesh> solids;
    std::optional<animkit::PointCache> moving;
    if (fs::exists(out / "colliders.obj")) solids = *animkit::read_obj_mesh(out / "colliders.obj");
    if (fs::exists(out / "colliders.pc2")) moving = *animkit::read_pc2(out / "colliders.pc2");
    for (std::size_t k = 0; k < cloth->frames.size(); ++k) {
      for (float v : cloth->frames[k]) ASSERT_TRUE(std::isfinite(v)) << "frame " << k;
      sheet->vertices = cache_frame(*cloth, k);
      if (scene.contains("ground")) {
        for (const animkit::Vec3& p : sheet->vertices) EXPECT_GT(p.y(), 0.0) << "frame " << k;
      }
      if (solids) {
        if (moving) solids->vertices = cache_frame(*moving, k);
        EXPECT_FALSE(animkit::audit::meshes_intersect(*sheet, *solids)) << "frame " << k;
      }
      if (random.self_contact()) {
        EXPECT_EQ(animkit::audit::count_self_intersections(*sheet), 0) << "frame " << k;
      }
    }
  }
  // Most scenes run (the generator tests runs, not only refusals).
  EXPECT_GE(2 * ran, scenes) << ran << " of " << scenes << " ran, " << refused << " refused";
  std::printf("random scenes: %d ran, %d refused\n", ran, refused);
}

}  // namespace hostile_input_cli_test
