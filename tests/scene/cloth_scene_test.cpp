#include "animkit/scene/cloth_scene.h"

#include <gtest/gtest.h>

namespace animkit {
namespace {

ClothScene lab_cloth() {
  auto scene = ClothScene::create();
  EXPECT_TRUE(scene.has_value()) << scene.error().message;
  return std::move(*scene);
}

int free_corner(const ClothScene& scene) {
  return grid_index(scene.options().grid.cells, scene.options().grid.cells,
                    scene.options().grid.cells);
}

TEST(ClothScene, TheMouseSpringPullsTheGrabbedParticleToTheCursor) {
  ClothScene held = lab_cloth(), free = lab_cloth();
  const int p = free_corner(held);
  const Vec3 target = held.simulator().state().position(p) + Vec3(0.0, 0.8, 0.0);
  ASSERT_TRUE(held.set_drag({p, target}).has_value());
  for (int i = 0; i < 90; ++i) {
    ASSERT_TRUE(held.step().has_value());
    ASSERT_TRUE(free.step().has_value());
  }
  const double held_gap = (held.simulator().state().position(p) - target).norm();
  const double free_gap = (free.simulator().state().position(p) - target).norm();
  EXPECT_LT(held_gap, 0.5 * free_gap);
  DrawList list;
  held.describe(list);
  EXPECT_EQ(list.points.back().position, target.cast<float>());  // the cursor is drawn
  held.clear_drag();
  EXPECT_FALSE(held.drag().has_value());
}

TEST(ClothScene, PinningHoldsAParticleAndUnpinningReleasesIt) {
  ClothScene scene = lab_cloth();
  const int corner = free_corner(scene);
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(scene.step().has_value());
  ASSERT_TRUE(scene.toggle_pin(corner).has_value());
  const Vec3 pinned_at = scene.simulator().state().position(corner);
  for (int i = 0; i < 30; ++i) ASSERT_TRUE(scene.step().has_value());
  EXPECT_EQ(scene.simulator().state().position(corner), pinned_at);

  const int lab_pin = grid_index(scene.options().grid.cells, 0, 0);
  ASSERT_TRUE(scene.simulator().model().pinned[lab_pin]);
  const double y = scene.simulator().state().position(lab_pin).y();
  ASSERT_TRUE(scene.toggle_pin(lab_pin).has_value());
  for (int i = 0; i < 30; ++i) ASSERT_TRUE(scene.step().has_value());
  EXPECT_LT(scene.simulator().state().position(lab_pin).y(), y - 0.01);

  const auto bad = scene.toggle_pin(121);
  ASSERT_FALSE(bad.has_value());
  EXPECT_EQ(bad.error().message, "particle 121 is out of range (the cloth has 121)");
}

TEST(ClothScene, ApplyKeepsTheMotionAndResetStartsOver) {
  ClothScene scene = lab_cloth();
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(scene.step().has_value());
  const ClothState moving = scene.simulator().state();
  ClothSceneOptions stiffer = scene.options();
  stiffer.grid.stiffness = 250.0;
  ASSERT_TRUE(scene.apply(stiffer).has_value());
  EXPECT_EQ(scene.simulator().state().positions, moving.positions);
  EXPECT_EQ(scene.simulator().model().stiffness.front(), 250.0);

  ClothSceneOptions bigger = scene.options();
  bigger.grid.cells = 14;
  ASSERT_TRUE(scene.apply(bigger).has_value());
  EXPECT_EQ(scene.simulator().model().particle_count(), 15 * 15);

  ClothSceneOptions broken = scene.options();
  broken.time_step = 0.0;
  const auto rejected = scene.apply(broken);
  ASSERT_FALSE(rejected.has_value());
  EXPECT_EQ(rejected.error().message, "time step must be a positive finite number, got 0");
  EXPECT_EQ(scene.options().grid.cells, 14);  // unchanged
}

TEST(ClothScene, PickFindsTheParticleUnderTheRay) {
  ClothScene scene = lab_cloth();
  const Vec3 p = scene.simulator().state().position(37);
  const Ray ray{p + Vec3(0.05, 3.0, 0.0), Vec3(0.0, -1.0, 0.0)};  // from above, a bit off
  EXPECT_EQ(scene.pick(ray, 0.06), 37);
  EXPECT_FALSE(scene.pick(ray, 0.01).has_value());
}

TEST(ClothScene, RecordsTheEnergyOfEveryStep) {
  ClothScene scene = lab_cloth();
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(scene.step().has_value());
  ASSERT_EQ(scene.energy_history().size(), 5u);
  EXPECT_EQ(scene.energy_history().back(), scene.last_step()->energy);
}

}  // namespace
}  // namespace animkit
