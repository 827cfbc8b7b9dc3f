// The library's output sinks on real runs: every file whole at the end of a run, none after a
// divergence or a failing sink (metrics excepted: they say how a run failed), and a run whose
// frames a .glb cannot hold refused before its first step.
#include <gtest/gtest.h>

#include <filesystem>

#include "../support/temp_files.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/io/gltf_sink.h"
#include "animkit/io/metrics_sink.h"
#include "animkit/io/obj_sink.h"
#include "animkit/io/point_cache_sink.h"

namespace animkit {
namespace {

namespace fs = std::filesystem;

ClothSimulator sheet(const GridClothOptions& grid, const SimulationOptions& options = {}) {
  auto sim = ClothSimulator::create(make_grid_cloth(grid), options);
  EXPECT_TRUE(sim) << sim.error().message;
  return std::move(*sim);
}

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(ClothSinks, ARunLeavesEveryFileWhole) {
  const fs::path dir = testing_support::fresh_dir("sinks_whole");
  ClothSimulator sim = sheet({.cells = 4});
  PointCacheSink cache(dir);
  ObjSink meshes(dir);
  GltfSink gltf(dir / "cloth.glb");
  ClothRunInfo info;
  info.integrator = "implicit-pcg";
  MetricsSink metrics(dir, info);
  ClothSink* const sinks[] = {&cache, &meshes, &gltf, &metrics};
  ASSERT_TRUE(run_cloth(sim, 3, 1.0 / 60.0, sinks));
  EXPECT_EQ(entries(dir),
            (std::vector<std::string>{"cloth.glb", "cloth.obj", "cloth.pc2", "metrics.json"}));
  const auto pc2 = read_pc2(dir / "cloth.pc2");
  ASSERT_TRUE(pc2);
  EXPECT_EQ(pc2->frames.size(), 4u);
  EXPECT_EQ(pc2->points, 25);
}

TEST(ClothSinks, ADivergedRunKeepsOnlyItsMetrics) {
  const fs::path dir = testing_support::fresh_dir("sinks_diverged");
  ClothSimulator sim = sheet({.cells = 6, .stiffness = 1e4}, {ExplicitEulerSettings{}, 1});
  PointCacheSink cache(dir);
  ObjSink meshes(dir);
  GltfSink gltf(dir / "cloth.glb");
  MetricsSink metrics(dir, {});
  ClothSink* const sinks[] = {&cache, &meshes, &gltf, &metrics};
  const auto run = run_cloth(sim, 600, 1.0 / 30.0, sinks);
  ASSERT_TRUE(run && run->divergence);
  EXPECT_EQ(entries(dir), std::vector<std::string>{"metrics.json"});
}

// Fails on its third frame, as a full disk would.
class FailingSink final : public ClothSink {
 public:
  Result<void> begin(const ClothFrame&, int, double) override { return {}; }
  Result<void> frame(const ClothFrame& frame) override {
    if (frame.frame == 3) return fail("No space left on device");
    return {};
  }
  Result<void> finish(const ClothRun&, const ClothFrame&) override { return {}; }
};

TEST(ClothSinks, AFailingSinkLeavesNoFileOfTheOthers) {
  const fs::path dir = testing_support::fresh_dir("sinks_failing");
  ClothSimulator sim = sheet({.cells = 4});
  {
    PointCacheSink cache(dir);
    GltfSink gltf(dir / "cloth.glb");
    FailingSink failing;
    ClothSink* const sinks[] = {&cache, &gltf, &failing};
    const auto run = run_cloth(sim, 10, 1.0 / 60.0, sinks);
    ASSERT_FALSE(run);
    EXPECT_EQ(run.error().message, "No space left on device");
  }
  EXPECT_TRUE(entries(dir).empty());
}

TEST(ClothSinks, ARunLongerThanAGlbHoldsIsRefusedBeforeItStarts) {
  const fs::path dir = testing_support::fresh_dir("sinks_long");
  ClothSimulator sim = sheet({.cells = 2});
  GltfSink gltf(dir / "cloth.glb");
  ClothSink* const sinks[] = {&gltf};
  const auto run = run_cloth(sim, kMaxGltfClothFrames, 1.0 / 60.0, sinks);
  ASSERT_FALSE(run);
  EXPECT_EQ(run.error().message,
            "cloth.glb: a cloth.glb holds at most 65535 frames (one morph target each), not 65536");
  EXPECT_EQ(sim.steps_taken(), 0);
}

}  // namespace
}  // namespace animkit
