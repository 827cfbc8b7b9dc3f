#include "animkit/scene/scene_registry.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "animkit/scene/cloth_scenes.h"

namespace animkit {
namespace {

TEST(SceneRegistry, ListsTheArmTheClipAndEveryClothSceneOnce) {
  std::set<std::string> names;
  for (const SceneEntry& entry : scene_entries()) {
    EXPECT_TRUE(names.insert(std::string(entry.name)).second) << entry.name;
    EXPECT_FALSE(entry.summary.empty()) << entry.name;
  }
  ASSERT_NE(find_scene("ik"), nullptr);
  EXPECT_EQ(find_scene("ik")->kind, SceneKind::ik);
  ASSERT_NE(find_scene("bvh"), nullptr);
  EXPECT_EQ(find_scene("bvh")->kind, SceneKind::bvh);
  for (const ClothSceneEntry& cloth : cloth_scenes()) {
    const SceneEntry* entry = find_scene(cloth.name);
    ASSERT_NE(entry, nullptr) << cloth.name;
    EXPECT_EQ(entry->kind, SceneKind::cloth);
  }
  EXPECT_EQ(scene_entries().size(), cloth_scenes().size() + 2);
  // Entries of one kind are together, so a menu of kinds can take the first of each.
  EXPECT_EQ(scene_entries()[0].kind, SceneKind::ik);
  EXPECT_EQ(scene_entries()[1].kind, SceneKind::bvh);
  EXPECT_EQ(scene_kind_title(SceneKind::bvh), "Motion capture");
}

TEST(SceneRegistry, ClothMeansTheLabsClothAndUnknownNamesAreNull) {
  ASSERT_NE(find_scene("cloth"), nullptr);
  EXPECT_EQ(find_scene("cloth")->name, "lab");
  EXPECT_EQ(find_scene("walk"), nullptr);
  EXPECT_EQ(scene_names().rfind("ik, bvh, lab, ", 0), 0u) << scene_names();
}

}  // namespace
}  // namespace animkit
