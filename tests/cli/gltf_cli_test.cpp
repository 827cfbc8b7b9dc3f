// Behaviour tests of the glTF files the CLI writes beside its other outputs: cloth.glb from
// `animkit cloth --out`, none with --no-gltf, fixed.glb from `animkit footlock`. What is inside
// them is checked by tests/io/*_gltf_test.cpp and by real clients (tests/gltf/).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "../support/run_command.h"
#include "../support/temp_files.h"

namespace gltf_cli_test {

namespace fs = std::filesystem;
using animkit::testing_support::read_file;
using animkit::testing_support::run_command;

const std::string kCli = ANIMKIT_CLI_PATH;
const fs::path kWalk = ANIMKIT_TEST_DATA_DIR "/cmu/131_01.bvh";

fs::path fresh_dir(const std::string& name) {
  return animkit::testing_support::fresh_dir("cli_gltf_" + name);
}

// The JSON chunk of a .glb (glTF 2.0, "GLB File Format Specification").
nlohmann::json glb_json(const fs::path& path) {
  const std::string bytes = read_file(path);
  EXPECT_GE(bytes.size(), 20u);
  EXPECT_EQ(bytes.substr(0, 4), "glTF");
  std::uint32_t length = 0, json_length = 0;
  std::memcpy(&length, bytes.data() + 8, 4);
  std::memcpy(&json_length, bytes.data() + 12, 4);
  EXPECT_EQ(length, bytes.size());
  EXPECT_EQ(bytes.substr(16, 4), "JSON");
  return nlohmann::json::parse(bytes.substr(20, json_length));
}

TEST(GltfCli, AClothRunWritesItsGlbBesideThePointCache) {
  const fs::path out = fresh_dir("cloth");
  const auto r = run_command(
      kCli + " cloth --scene spinning-sphere --frames 4 --no-picture --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("cloth.glb"), std::string::npos) << r.out;
  const nlohmann::json gltf = glb_json(out / "cloth.glb");
  EXPECT_EQ(gltf["asset"]["version"], "2.0");
  // The sheet with a morph target for each of the 4 frames after the start, and the turning
  // ball animated by its node.
  EXPECT_EQ(gltf["meshes"][0]["primitives"][0]["targets"].size(), 4u);
  EXPECT_EQ(gltf["nodes"][0]["name"], "cloth");
  ASSERT_EQ(gltf["nodes"].size(), 2u);
  bool ball_turns = false;
  for (const auto& channel : gltf["animations"][0]["channels"]) {
    ball_turns =
        ball_turns || (channel["target"]["node"] == 1 && channel["target"]["path"] == "rotation");
  }
  EXPECT_TRUE(ball_turns);
}

TEST(GltfCli, NoGltfWritesNone) {
  const fs::path out = fresh_dir("none");
  const auto r =
      run_command(kCli + " cloth --frames 2 --no-picture --no-gltf --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(out / "cloth.glb"));
  EXPECT_TRUE(fs::exists(out / "cloth.pc2"));
  EXPECT_EQ(r.out.find("cloth.glb"), std::string::npos) << r.out;
}

TEST(GltfCli, ADivergedRunWritesNoGlb) {
  const fs::path out = fresh_dir("diverged");
  const auto r = run_command(kCli +
                             " cloth --integrator explicit --substeps 1 --stiffness 300 --dt 0.1 "
                             "--frames 200 --no-picture --out " +
                             out.string());
  ASSERT_EQ(r.exit_code, 2) << r.out;
  EXPECT_TRUE(fs::exists(out / "metrics.json"));
  EXPECT_FALSE(fs::exists(out / "cloth.glb"));
}

TEST(GltfCli, FootLockWritesTheFixedWalkInMetres) {
  if (!fs::exists(kWalk)) GTEST_SKIP() << kWalk << " is not here";
  const fs::path out = fresh_dir("walk");
  const auto r = run_command(kCli + " footlock --in " + kWalk.string() +
                             " --scale 0.056444 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("fixed.glb"), std::string::npos) << r.out;
  const nlohmann::json gltf = glb_json(out / "fixed.glb");
  // 38 joints (End Sites included) and the figure, keyed over the clip's 994 frames; the hips
  // walk about a metre up (metres, not CMU's units: some 17 of them).
  ASSERT_EQ(gltf["nodes"].size(), 39u);
  EXPECT_EQ(gltf["nodes"][0]["name"], "Hips");
  const auto& animation = gltf["animations"][0];
  int hips_moves = 0;
  for (const auto& channel : animation["channels"]) {
    if (channel["target"]["node"] != 0 || channel["target"]["path"] != "translation") continue;
    ++hips_moves;
    const int output = animation["samplers"][channel["sampler"].get<int>()]["output"];
    const double highest = gltf["accessors"][output]["max"][1];
    EXPECT_GT(highest, 0.8);
    EXPECT_LT(highest, 1.2);
  }
  EXPECT_EQ(hips_moves, 1);
  EXPECT_EQ(gltf["skins"][0]["joints"].size(), 38u);
  EXPECT_GT(gltf["animations"][0]["channels"].size(), 20u);  // every joint the walk turns
  const auto& times = gltf["accessors"][gltf["animations"][0]["samplers"][0]["input"].get<int>()];
  EXPECT_EQ(times["count"], 994);
  EXPECT_NEAR(times["max"][0].get<double>(), 993 * 0.0083333, 1e-3);
}

}  // namespace gltf_cli_test
