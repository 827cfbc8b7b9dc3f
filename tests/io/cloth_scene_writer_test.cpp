// Built-in scenes written as scene files: reading the file back gives the same scene (written
// again it is the same text, and its first steps the same cloth), and what the format cannot
// hold (triangle meshes, kept in OBJ files) is refused by name.
#include "animkit/io/cloth_scene_writer.h"

#include <gtest/gtest.h>

#include "animkit/io/cloth_scene_file.h"
#include "animkit/scene/cloth_scenes.h"

namespace animkit {
namespace {

// The cloth after `steps` steps of the scene.
Eigen::VectorXd positions_after(const ClothWorldDesc& desc, int steps) {
  auto world = build_cloth_world(desc);
  EXPECT_TRUE(world) << world.error().message;
  for (int k = 0; k < steps; ++k) EXPECT_TRUE(world->simulator.step(desc.time_step));
  return world->simulator.state().positions;
}

TEST(ClothSceneWriter, EveryBuiltInSceneReadsBackAsItself) {
  for (const ClothSceneEntry& entry : cloth_scenes()) {
    SCOPED_TRACE(std::string(entry.name));
    const ClothWorldDesc scene = entry.make();
    const auto json = cloth_scene_json(scene);
    ASSERT_TRUE(json) << json.error().message;
    const auto read = parse_cloth_scene(*json, "scene.json", ".");
    ASSERT_TRUE(read) << read.error().message;
    EXPECT_EQ(*cloth_scene_json(*read), *json);
    EXPECT_EQ(read->frames, scene.frames);
    EXPECT_EQ(read->time_step, scene.time_step);
    EXPECT_EQ(read->colliders.size(), scene.colliders.size());
    EXPECT_EQ(read->material_name, scene.material_name);
    // The same cloth after two steps (a turned sheet's rotation goes through an angle and an
    // axis, so the last bits may differ).
    const Eigen::VectorXd a = positions_after(scene, 2), b = positions_after(*read, 2);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_LT((a - b).lpNorm<Eigen::Infinity>(), 1e-9);
  }
}

TEST(ClothSceneWriter, KeyframesAndCustomMaterialsAreWritten) {
  ClothWorldDesc scene = cotton_sheet_world(4, 1.0, 0.5);
  std::get<GridClothOptions>(scene.cloth).material->stretch = 777.0;  // no preset any more
  ColliderDesc lift;
  lift.name = "lift [left, \"inner\"]";  // brackets, a comma and quotes in a name
  lift.shape = BoxShape{Vec3(0.1, 0.05, 0.1)};
  lift.motion = KeyframedMotion{{{.time = 0.0, .position = Vec3(0, 0.1, 0)},
                                 {.time = 1.0,
                                  .position = Vec3(0, 0.3, 0),
                                  .rotation = Quat(Eigen::AngleAxisd(0.5, Vec3::UnitY()))}}};
  scene.colliders.push_back(lift);
  const auto json = cloth_scene_json(scene);
  ASSERT_TRUE(json) << json.error().message;
  EXPECT_NE(json->find("\"stretch\": 777.0"), std::string::npos) << *json;
  EXPECT_NE(json->find("\"keyframes\""), std::string::npos) << *json;
  const auto read = parse_cloth_scene(*json, "scene.json", ".");
  ASSERT_TRUE(read) << read.error().message;
  EXPECT_EQ(read->colliders[0].name, lift.name);
  const auto& keys = std::get<KeyframedMotion>(read->colliders[0].motion).keyframes;
  ASSERT_EQ(keys.size(), 2u);
  EXPECT_TRUE(keys[1].rotation.isApprox(Quat(Eigen::AngleAxisd(0.5, Vec3::UnitY())), 1e-15));
  EXPECT_EQ(std::get<GridClothOptions>(read->cloth).material->stretch, 777.0);
}

TEST(ClothSceneWriter, TriangleMeshesAreRefused) {
  ClothWorldDesc scene = cotton_sheet_world(4, 1.0, 0.5);
  ColliderDesc rock;
  rock.name = "rock";
  rock.shape = MeshShape{TriangleMesh{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {{0, 1, 2}}}};
  scene.colliders.push_back(rock);
  EXPECT_EQ(cloth_scene_json(scene).error().message,
            "collider 'rock' is a triangle mesh, which a scene file takes from an OBJ file: not "
            "written");
}

}  // namespace
}  // namespace animkit
