// A scene named as the user names it: a built-in scene by name, a JSON file by path, and one
// error for anything else that lists the choices.
#include "animkit/io/cloth_scene_source.h"

#include <gtest/gtest.h>

#include <fstream>

#include "../support/temp_files.h"
#include "animkit/scene/cloth_scenes.h"

namespace animkit {
namespace {

TEST(ClothSceneSource, EveryBuiltInSceneByItsName) {
  for (const ClothSceneEntry& entry : cloth_scenes()) {
    const auto scene = open_cloth_scene(entry.name);
    ASSERT_TRUE(scene) << scene.error().message;
    EXPECT_EQ(scene->colliders.size(), entry.make().colliders.size()) << entry.name;
    EXPECT_EQ(scene->frames, entry.make().frames) << entry.name;
  }
}

TEST(ClothSceneSource, AJsonFileByItsPath) {
  const auto dir = testing_support::fresh_dir("cloth_scene_source");
  std::ofstream(dir / "ball.json") << R"({"cloth": {"grid": 6}, "frames": 12,
    "colliders": [{"name": "ball", "shape": "sphere", "radius": 0.2, "position": [1, 0.5, 0]}]})";
  const auto scene = open_cloth_scene((dir / "ball.json").string());
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(std::get<GridClothOptions>(scene->cloth).cells, 6);
  EXPECT_EQ(scene->frames, 12);
  ASSERT_EQ(scene->colliders.size(), 1u);
  EXPECT_EQ(scene->colliders[0].name, "ball");
  const auto missing = open_cloth_scene((dir / "none.json").string());
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().message.find("none.json"), std::string::npos);
}

TEST(ClothSceneSource, AnythingElseIsRefusedWithTheChoices) {
  const auto unknown = open_cloth_scene("drape");
  ASSERT_FALSE(unknown);
  EXPECT_EQ(unknown.error().message,
            "unknown scene 'drape' (expected a .json file or one of: " + cloth_scene_names() + ")");
}

}  // namespace
}  // namespace animkit
