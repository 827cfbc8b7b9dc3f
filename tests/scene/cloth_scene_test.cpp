#include "animkit/scene/cloth_scene.h"

#include <gtest/gtest.h>

#include "animkit/cloth/integrator_registry.h"

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
  EXPECT_EQ(rejected.error().message, "time step must be between 1e-06 and 10, got 0");
  EXPECT_EQ(scene.options().grid.cells, 14);  // unchanged
}

TEST(ClothScene, PickFindsTheParticleUnderTheCursorNearestTheEye) {
  ClothScene scene = lab_cloth();
  // Straight down from above the sheet: every particle projects apart.
  OrbitCamera camera;
  camera.focus = Vec3(1.0, 1.5, 0.0);
  camera.pitch = 1.5;
  camera.distance = 4.0;
  const auto at = camera.project(scene.simulator().state().position(37), 800.0, 600.0);
  ASSERT_TRUE(at.has_value());
  EXPECT_EQ(scene.pick(camera, at->x() + 3.0, at->y(), 800.0, 600.0, 6.0), 37);
  EXPECT_FALSE(scene.pick(camera, at->x() + 30.0, at->y() + 30.0, 800.0, 600.0, 2.0).has_value());
  // Edge-on along a grid row, particles line up one behind another: the nearest one wins.
  OrbitCamera side;
  side.focus = Vec3(1.0, 1.5, 0.0);
  side.yaw = 1.5707963267948966;  // looking from +x towards -x, along the row of particles
  side.pitch = 0.0;
  side.distance = 5.0;
  const int near_end = grid_index(10, 10, 5), far_end = grid_index(10, 0, 5);
  const auto p = side.project(scene.simulator().state().position(near_end), 800.0, 600.0);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(scene.pick(side, p->x(), p->y(), 800.0, 600.0, 4.0), near_end);
  EXPECT_NE(scene.pick(side, p->x(), p->y(), 800.0, 600.0, 4.0), far_end);
}

TEST(ClothScene, ReleasingTheDragRemovesItsForce) {
  ClothScene dragged = lab_cloth();
  const int p = free_corner(dragged);
  ASSERT_TRUE(dragged.set_drag({p, Vec3(3.0, 3.0, 0.0)}).has_value());
  ASSERT_TRUE(dragged.step().has_value());
  dragged.clear_drag();
  // From the same state, the released cloth steps exactly as a cloth never dragged.
  const ClothState after_drag = dragged.simulator().state();
  ASSERT_TRUE(dragged.step().has_value());
  ClothSimulator reference = *ClothSimulator::create(make_grid_cloth(), {});
  ASSERT_TRUE(reference.set_state(after_drag).has_value());
  ASSERT_TRUE(reference.step(dragged.options().time_step).has_value());
  EXPECT_LT((reference.state().positions - dragged.simulator().state().positions).norm(), 1e-12);
}

TEST(ClothScene, TheMouseSpringStaysStableAtTheLargestTimeStep) {
  ClothSceneOptions options;
  options.time_step = 0.1;  // the viewer's slider maximum
  for (const IntegratorEntry& entry : cloth_integrators()) {
    options.simulation.integrator = entry.defaults;
    auto scene = ClothScene::create(options);
    ASSERT_TRUE(scene.has_value());
    const int p = free_corner(*scene);
    const Vec3 target(2.5, 2.5, 1.0);
    ASSERT_TRUE(scene->set_drag({p, target}).has_value());
    for (int i = 0; i < 100; ++i) ASSERT_TRUE(scene->step().has_value()) << "step " << i;
    EXPECT_LT((scene->simulator().state().position(p) - target).norm(), 1.5);
  }
}

TEST(ClothScene, RecordsTheEnergyOfEveryStep) {
  ClothScene scene = lab_cloth();
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(scene.step().has_value());
  ASSERT_EQ(scene.energy_history().size(), 5u);
  EXPECT_EQ(scene.energy_history().back(), scene.last_step()->energy);
}

}  // namespace
}  // namespace animkit
