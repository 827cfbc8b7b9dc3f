// Building a world from its description: the lab's unchanged, contact and air wired in, and
// clear errors for worlds that cannot start.
#include "animkit/cloth/cloth_world.h"

#include <gtest/gtest.h>

namespace animkit {
namespace {

TEST(ClothWorld, TheDefaultIsTheLabsClothBitForBit) {
  auto world = build_cloth_world({});
  ASSERT_TRUE(world) << world.error().message;
  auto lab = ClothSimulator::create(make_grid_cloth(), {});
  ASSERT_TRUE(lab);
  EXPECT_FALSE(world->contact);
  EXPECT_FALSE(world->air);
  for (int k = 0; k < 20; ++k) {
    ASSERT_TRUE(world->simulator.step(1.0 / 60.0));
    ASSERT_TRUE(lab->step(1.0 / 60.0));
  }
  EXPECT_EQ(world->simulator.state().positions, lab->state().positions);
}

ClothWorldDesc sheet_over_ball() {
  ClothWorldDesc desc;
  GridClothOptions grid;
  grid.cells = 8;
  grid.size = 1.0;
  grid.height = 0.5;
  grid.pins = GridPins::none;
  grid.offset = Vec3(-0.5, 0.0, 0.0);
  desc.cloth = grid;
  ColliderDesc ball;
  ball.name = "ball";
  ball.shape = SphereShape{0.2};
  ball.motion = ScriptedMotion{.initial = {.position = Vec3(0, 0.2, 0)}};
  desc.colliders.push_back(ball);
  desc.ground = GroundDesc{};
  return desc;
}

TEST(ClothWorld, ContactIsWiredAndReportsEachStep) {
  auto world = build_cloth_world(sheet_over_ball());
  ASSERT_TRUE(world) << world.error().message;
  ASSERT_TRUE(world->contact);
  ASSERT_TRUE(world->friction);  // the default coefficients are not zero
  ASSERT_EQ(world->colliders.size(), 1u);
  // Newton gets room for impacts.
  EXPECT_GE(std::get<NewtonSettings>(world->simulator.options().integrator).max_iterations,
            kContactNewtonIterations);
  auto step = world->simulator.step(1.0 / 60.0);
  ASSERT_TRUE(step) << step.error().message;
  EXPECT_TRUE(step->has_contact);
  EXPECT_GT(step->min_contact_distance, 0.0);
}

TEST(ClothWorld, NoFrictionTermWhenEveryCoefficientIsZero) {
  ClothWorldDesc desc = sheet_over_ball();
  desc.colliders[0].friction = 0.0;
  desc.ground->friction = 0.0;
  desc.self_friction = 0.0;
  auto world = build_cloth_world(desc);
  ASSERT_TRUE(world) << world.error().message;
  EXPECT_FALSE(world->friction);
  desc.friction_passes = 0;
  EXPECT_EQ(build_cloth_world(desc).error().message, "friction passes must be at least 1, got 0");
}

TEST(ClothWorld, PlacesAndPinsTheGrid) {
  GridClothOptions grid;
  grid.cells = 4;
  grid.pins = GridPins::edge;
  grid.rotation = Quat(Eigen::AngleAxisd(0.5 * M_PI, Vec3::UnitX()));
  grid.offset = Vec3(1, 2, 3);
  const ClothDesc desc = make_grid_cloth(grid);
  int pinned = 0;
  for (const ParticleDesc& p : desc.particles) pinned += p.pinned ? 1 : 0;
  EXPECT_EQ(pinned, 5);
  // Particle (i, j) = (0, 0) was at (0, 1.5, -1): turned about the centre (1, 1.5, 0), moved.
  EXPECT_NEAR((desc.particles[0].position - Vec3(0 + 1, 1.5 + 1 + 2, 0 + 3)).norm(), 0.0, 1e-12);
  grid.pins = GridPins::none;
  for (const ParticleDesc& p : make_grid_cloth(grid).particles) EXPECT_FALSE(p.pinned);
}

TEST(ClothWorld, RefusesAClothStartingInsideACollider) {
  ClothWorldDesc desc = sheet_over_ball();
  std::get<ScriptedMotion>(desc.colliders[0].motion).initial.position = Vec3(0, 0.5, 0);
  const auto world = build_cloth_world(desc);
  ASSERT_FALSE(world);
  EXPECT_EQ(world.error().message, "particle 30 starts inside collider 'ball'");
}

TEST(ClothWorld, RefusesBadWorlds) {
  ClothWorldDesc desc = sheet_over_ball();
  desc.ground->height = 0.6;
  EXPECT_EQ(build_cloth_world(desc).error().message, "particle 0 starts on or below the ground");
  desc = sheet_over_ball();
  desc.colliders[0].shape = PlaneShape{};
  EXPECT_EQ(build_cloth_world(desc).error().message,
            "collider 'ball': contact takes no plane collider; give a floor as the scene's "
            "ground");
  desc = sheet_over_ball();
  desc.colliders.push_back(desc.colliders[0]);
  EXPECT_EQ(build_cloth_world(desc).error().message, "two colliders are named 'ball'");
  desc = sheet_over_ball();
  desc.time_step = 0.0;
  EXPECT_EQ(build_cloth_world(desc).error().message,
            "the time step (s) must be between 1e-06 and 10, got 0");
  desc = sheet_over_ball();
  std::get<GridClothOptions>(desc.cloth).rotation = Quat(2, 0, 0, 0);
  EXPECT_EQ(build_cloth_world(desc).error().message, "cloth rotation must be a unit quaternion");
}

}  // namespace
}  // namespace animkit
