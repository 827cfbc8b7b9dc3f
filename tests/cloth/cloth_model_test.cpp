#include "animkit/cloth/cloth_model.h"

#include <gtest/gtest.h>

#include <limits>

#include "animkit/cloth/grid_cloth.h"

namespace animkit {
namespace {

std::string build_error(const ClothDesc& desc) {
  const auto built = build_cloth(desc);
  return built ? "(built)" : built.error().message;
}

TEST(GridCloth, TheLabsClothByDefault) {
  const ClothDesc desc = make_grid_cloth();
  const auto built = build_cloth(desc);
  ASSERT_TRUE(built);
  const ClothModel& m = built->model;
  EXPECT_EQ(m.particle_count(), 121);
  // 2 axes x (11 x 10 neighbours at distance 1 + 11 x 9 at distance 2) + 2 x 10 x 10 diagonals.
  EXPECT_EQ(m.spring_count(), 618);
  EXPECT_EQ(m.triangles.size(), 200u);
  int pinned = 0;
  for (char p : m.pinned) pinned += p;
  EXPECT_EQ(pinned, 2);
  EXPECT_TRUE(m.pinned[grid_index(10, 0, 0)]);
  EXPECT_TRUE(m.pinned[grid_index(10, 0, 10)]);
  EXPECT_EQ(built->state.position(grid_index(10, 0, 0)), Vec3(0.0, 1.5, -1.0));
  EXPECT_EQ(built->state.position(grid_index(10, 10, 10)), Vec3(2.0, 1.5, 1.0));
  EXPECT_NEAR(m.rest_length[0], 0.2, 1e-15);
  EXPECT_EQ(m.stiffness[0], 100.0);
  EXPECT_EQ(m.mass[5], 1.0);
  EXPECT_EQ(m.gravity, 0.3);
  EXPECT_EQ(m.damping, 0.2);
  EXPECT_EQ(built->state.velocities.norm(), 0.0);
}

TEST(GridCloth, AnySize) {
  const auto built = build_cloth(make_grid_cloth({.cells = 40}));
  ASSERT_TRUE(built);
  EXPECT_EQ(built->model.particle_count(), 41 * 41);
  EXPECT_NEAR(built->model.rest_length[0], 0.05, 1e-15);
  EXPECT_EQ(build_error(make_grid_cloth({.cells = 0})), "the cloth has no particles");
}

TEST(ClothDesc, NamesTheFirstProblem) {
  ClothDesc desc = make_grid_cloth({.cells = 2});
  desc.particles[4].mass = -1.0;
  EXPECT_EQ(build_error(desc), "particle 4 mass must be between 1e-06 and 1e+06, got -1");
  desc = make_grid_cloth({.cells = 2});
  desc.particles[3].position.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(build_error(desc), "particle 3 has a non-finite position");
  desc = make_grid_cloth({.cells = 2});
  desc.springs[17] = {4, 4, -1.0, 100.0};
  EXPECT_EQ(build_error(desc), "spring 17 joins particle 4 to itself");
  desc.springs[17] = {4, 99, -1.0, 100.0};
  EXPECT_EQ(build_error(desc), "spring 17 joins particles 4 and 99, but there are 9");
  desc.springs[17] = {4, 5, -1.0, 0.0};
  EXPECT_EQ(build_error(desc), "spring 17 stiffness must be between 1e-06 and 1e+09, got 0");
  desc.springs[17] = {4, 5, 0.0, 100.0};
  EXPECT_EQ(build_error(desc), "spring 17 has zero rest length");
  desc = make_grid_cloth({.cells = 2});
  desc.damping = -0.5;
  EXPECT_EQ(build_error(desc), "damping must be between 0 and 1e+06, got -0.5");
}

TEST(ClothEnergy, SumsItsParts) {
  ClothDesc desc;
  desc.particles = {{Vec3(0, 1, 0), Vec3(1, 0, 0), 2.0, false},
                    {Vec3(0, 2, 0), Vec3::Zero(), 1.0, true}};
  desc.springs = {{0, 1, 0.5, 10.0}};
  desc.gravity = 0.5;
  const auto built = build_cloth(desc);
  ASSERT_TRUE(built);
  const ClothEnergy e = cloth_energy(built->model, built->state);
  EXPECT_DOUBLE_EQ(e.kinetic, 1.0);                // 1/2 * 2 * 1^2
  EXPECT_DOUBLE_EQ(e.elastic, 0.5 * 10.0 * 0.25);  // stretched 0.5 past its rest length
  EXPECT_DOUBLE_EQ(e.gravitational, 2.0 * 0.5 * 1.0 + 1.0 * 0.5 * 2.0);
  EXPECT_DOUBLE_EQ(e.total, e.kinetic + e.elastic + e.gravitational);
}

}  // namespace
}  // namespace animkit
