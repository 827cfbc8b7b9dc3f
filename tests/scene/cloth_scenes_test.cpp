// The built-in cloth scenes: each builds, and every frame of each, run as the CLI runs it, is
// intersection-free by an exact audit that shares no code with the solver (CGAL's predicates:
// the cloth against itself and against every collider; above the ground by comparison), every
// step converged.
#include "animkit/scene/cloth_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "../support/world_audit.h"

namespace animkit {
namespace {

TEST(ClothScenes, NamesAreDistinctAndTheLabsComesFirst) {
  std::set<std::string_view> names;
  for (const ClothSceneEntry& entry : cloth_scenes()) EXPECT_TRUE(names.insert(entry.name).second);
  EXPECT_EQ(cloth_scenes().front().name, "lab");
  EXPECT_EQ(find_cloth_scene("drape-sphere")->name, "drape-sphere");
  EXPECT_EQ(find_cloth_scene("nope"), nullptr);
  for (const char* name : {"drape-sphere", "tablecloth", "flag", "spinning-sphere", "fold"})
    EXPECT_NE(find_cloth_scene(name), nullptr) << name;
}

TEST(ClothScenes, EveryOneBuilds) {
  for (const ClothSceneEntry& entry : cloth_scenes()) {
    const ClothWorldDesc desc = entry.make();
    EXPECT_FALSE(desc.validate()) << entry.name;
    auto world = build_cloth_world(desc);
    EXPECT_TRUE(world) << entry.name << ": " << world.error().message;
  }
}

class BuiltinSceneAuditSlow : public ::testing::TestWithParam<std::string_view> {};

TEST_P(BuiltinSceneAuditSlow, EveryFrameIsIntersectionFreeAndConverged) {
  const ClothWorldDesc desc = find_cloth_scene(GetParam())->make();
  auto world = build_cloth_world(desc);
  ASSERT_TRUE(world) << world.error().message;
  ClothSimulator& sim = world->simulator;
  for (int frame = 1; frame <= desc.frames; ++frame) {
    auto step = sim.step(desc.time_step);
    ASSERT_TRUE(step) << "frame " << frame << ": " << step.error().message;
    ASSERT_TRUE(step->converged) << "frame " << frame;
    ASSERT_EQ(audit::world_frame_problem(*world, desc, frame), "") << "frame " << frame;
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, BuiltinSceneAuditSlow,
                         ::testing::Values("lab", "drape-sphere", "tablecloth", "flag",
                                           "spinning-sphere", "fold"),
                         [](const auto& scene) {
                           std::string name(scene.param);
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace animkit
