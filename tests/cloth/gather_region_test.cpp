// The region where a gathered pair set stays complete (src/cloth/contact/gather_region.h), and
// the contact term's reuse of its pairs inside it: a term that gathered once sees, anywhere in
// the region, exactly the contacts a term gathering there afresh sees (same active pairs, same
// value and gradient); the set holds only the pairs that can come within the thickness there;
// a step leaving the region gathers again; resting cloth runs the broad phase a few times, not
// twice per Newton iteration.
#include "../../src/cloth/contact/gather_region.h"

#include "../../src/cloth/contact/contact_candidates.h"
#include "../../src/cloth/contact/contact_pair.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/contact.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/integrator_registry.h"
#include "animkit/collision/collider_surface.h"

namespace animkit {
namespace {

TEST(GatherRegion, HoldsThePointsOfItsBoxesOnlyWithTheObstaclesWhereTheyWere) {
  GatherRegion region;
  const Eigen::VectorXd x = Eigen::Vector3d(1.0, 2.0, 3.0);
  const Eigen::VectorXd obstacles = Eigen::Vector3d(0.0, 0.0, 0.0);
  EXPECT_FALSE(region.covers(x, obstacles));  // nothing gathered yet
  const Eigen::VectorXd step = Eigen::Vector3d(0.1, -0.2, 0.0);
  region.set(x, &step, 0.01, obstacles);
  // Per axis from x to x + 1.5 step, widened by 0.01 on both sides.
  EXPECT_NEAR(region.lower()[0], 1.0 - 0.01, 1e-15);
  EXPECT_NEAR(region.lower()[1], 2.0 - 0.3 - 0.01, 1e-15);
  EXPECT_NEAR(region.lower()[2], 3.0 - 0.01, 1e-15);
  EXPECT_NEAR(region.extent()[0], 0.15 + 0.02, 1e-15);
  EXPECT_NEAR(region.extent()[1], 0.3 + 0.02, 1e-15);
  EXPECT_NEAR(region.extent()[2], 0.02, 1e-15);
  EXPECT_TRUE(region.covers(x, obstacles));
  EXPECT_TRUE(region.covers_step(x, step));
  EXPECT_TRUE(region.covers(Eigen::VectorXd(Eigen::Vector3d(1.14, 1.71, 3.0)), obstacles));
  EXPECT_FALSE(region.covers(Eigen::VectorXd(Eigen::Vector3d(1.0, 2.0, 3.02)), obstacles));
  EXPECT_FALSE(region.covers(Eigen::VectorXd(Eigen::Vector3d(0.98, 2.0, 3.0)), obstacles));
  EXPECT_FALSE(region.covers_step(x, Eigen::Vector3d(0.0, 0.0, 0.02)));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(region.covers(Eigen::VectorXd(Eigen::Vector3d(nan, 2.0, 3.0)), obstacles));
  EXPECT_FALSE(region.covers_step(x, Eigen::Vector3d(0.0, nan, 0.0)));
  EXPECT_FALSE(region.covers(x, Eigen::VectorXd(Eigen::Vector3d(0.0, 1e-9, 0.0))));  // moved
  // The farthest corner of the box from x: 0.15 + 0.01 along x, 0.3 + 0.01 along y, 0.01.
  EXPECT_NEAR(region.reach(0), std::sqrt(0.16 * 0.16 + 0.31 * 0.31 + 0.01 * 0.01), 1e-15);
  region.clear();
  EXPECT_FALSE(region.covers(x, obstacles));
}

// A cotton sheet folded over itself above the ground and against a ball: point-triangle and
// edge-edge self pairs, pairs with the ball's triangles, edges and vertices, and ground pairs.
struct FoldedSheet {
  ClothModel model;
  Eigen::VectorXd x;
  ContactObstacles obstacles;
};

FoldedSheet folded_sheet() {
  constexpr int kCells = 12;
  constexpr double kSize = 0.24;
  GridClothOptions grid{.cells = kCells, .size = kSize, .gravity = 9.81};
  grid.material = ClothMaterial{};
  ClothDesc desc = make_grid_cloth(grid);
  // Rows past the middle fold back over the first half, 2.5 mm above it; the lower layer lies
  // 1.5 mm above the ground.
  const double spacing = kSize / kCells;
  for (int i = 0; i <= kCells; ++i) {
    for (int j = 0; j <= kCells; ++j) {
      ParticleDesc& p = desc.particles[grid_index(kCells, i, j)];
      p.pinned = false;
      const double along = i <= kCells / 2 ? i * spacing : (kCells - i) * spacing;
      const double height = i <= kCells / 2 ? 1.5e-3 : 4e-3;
      p.position = Vec3(j * spacing, height, along);
    }
  }
  auto sim = ClothSimulator::create(desc, {find_integrator("implicit-multigrid")->defaults, 0});
  EXPECT_TRUE(sim) << sim.error().message;
  FoldedSheet sheet{sim->model(), sim->state().positions, {}};
  // A ball of radius 5 cm over the sheet's middle, its lowest point 1.5 mm above the upper layer.
  TriangleMesh ball = collider_surface(SphereShape{0.05}, 3);
  for (Vec3& v : ball.vertices) v += Vec3(0.5 * kSize, 4e-3 + 1.5e-3 + 0.05, 0.25 * kSize);
  sheet.obstacles.meshes.push_back(std::move(ball));
  sheet.obstacles.ground_height = 0.0;
  return sheet;
}

std::shared_ptr<ContactTerm> contact_for(const FoldedSheet& sheet) {
  auto term = ContactTerm::create(std::make_shared<const ClothModel>(sheet.model),
                                  {.thickness = 2e-3}, sheet.obstacles);
  EXPECT_TRUE(term) << term.error().message;
  ClothState state;
  state.positions = sheet.x;
  state.velocities = Eigen::VectorXd::Zero(sheet.x.size());
  (*term)->prepare(state, 1.0 / 60.0);  // the edges' rest lengths, from x
  return *term;
}

TEST(GatherRegion, PairsGatheredOnceSeeEverywhereInTheRegionWhatAFreshGatherSees) {
  const FoldedSheet sheet = folded_sheet();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0), move(-1e-3, 1e-3);
  int compared = 0, most_active = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const auto reused = contact_for(sheet);
    // One gather, for a random step from x: its region holds x and x + step.
    Eigen::VectorXd step(sheet.x.size());
    for (Eigen::Index k = 0; k < step.size(); ++k) step[k] = move(rng);
    ASSERT_GT(reused->max_step(sheet.x, step), 0.0);
    const std::int64_t gathers = reused->stats(sheet.x).gathers;
    // Points of the region (each coordinate anywhere in its box, which goes past the step):
    // the term keeps its pairs, and sees what a new term gathering there sees.
    GatherRegion region;
    region.set(sheet.x, &step, GatherRegion::kFloorFraction * 2e-3, Eigen::VectorXd());
    for (int sample = 0; sample < 6; ++sample) {
      // Anywhere in the region, or within 0.4 mm of x (inside the floor): far moves cross
      // layers, where the barrier is infinite, so the values are compared on the near ones.
      Eigen::VectorXd x(sheet.x.size());
      for (Eigen::Index k = 0; k < x.size(); ++k) {
        x[k] = sample % 2 == 0 ? region.lower()[k] + unit(rng) * region.extent()[k]
                               : sheet.x[k] + 0.4e-3 * (2.0 * unit(rng) - 1.0);
      }
      reused->update(x);
      const auto fresh = contact_for(sheet);
      fresh->update(x);
      const ContactStats seen = reused->stats(x), expected = fresh->stats(x);
      ASSERT_EQ(seen.gathers, gathers) << "a point inside the region gathered again";
      ASSERT_EQ(seen.active_pairs, expected.active_pairs) << trial << " " << sample;
      EXPECT_EQ(seen.min_distance, expected.min_distance);
      most_active = std::max(most_active, expected.active_pairs);
      const double value = reused->value(x);
      if (!std::isfinite(value)) continue;  // the random move crossed a pair over
      EXPECT_EQ(value, fresh->value(x));
      Eigen::VectorXd g1 = Eigen::VectorXd::Zero(x.size()), g2 = g1;
      reused->add_gradient(x, g1);
      fresh->add_gradient(x, g2);
      EXPECT_EQ(g1, g2);
      ++compared;
    }
  }
  EXPECT_GT(compared, 50);
  EXPECT_GT(most_active, 100);  // the scene does bring many pairs into play
}

TEST(GatherRegion, KeepsOnlyThePairsThatCanComeWithinTheThicknessInsideTheRegion) {
  const FoldedSheet sheet = folded_sheet();
  const auto term = contact_for(sheet);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> move(-2e-3, 2e-3);
  Eigen::VectorXd step(sheet.x.size());
  for (Eigen::Index k = 0; k < step.size(); ++k) step[k] = move(rng);
  ASSERT_GT(term->max_step(sheet.x, step), 0.0);
  // What the broad phase finds for the same boxes, and which of those pairs can come within
  // the thickness: their distance at x less the reaches of their two primitives.
  constexpr double kThickness = 2e-3;
  GatherRegion region;
  region.set(sheet.x, &step, GatherRegion::kFloorFraction * kThickness,
             term->geometry().obstacle_positions);
  ContactPairFinder finder;
  std::vector<ContactPair> found;
  ASSERT_TRUE(finder.gather(term->geometry(), region.lower(), &region.extent(), kThickness,
                            sheet.obstacles.ground_height, found));
  const int n = sheet.model.particle_count();
  int reachable = 0;
  for (const ContactPair& pair : found) {
    if (pair.kind == ContactKind::ground) {
      ++reachable;
      continue;
    }
    std::array<Vec3, 4> p;
    double reach = 0.0, first = 0.0;
    for (int i = 0; i < 4; ++i) {
      const int v = pair.vertices[i];
      p[i] = v < n ? Vec3(sheet.x.segment<3>(3 * v))
                   : Vec3(term->geometry().obstacle_positions.segment<3>(3 * (v - n)));
      const bool in_first = i < (pair.kind == ContactKind::point_triangle ? 1 : 2);
      const double r = v < n ? region.reach(v) : 0.0;
      (in_first ? first : reach) = std::max(in_first ? first : reach, r);
    }
    if (std::sqrt(contact_distance_squared(pair, p, 0.0)) < kThickness + first + reach)
      ++reachable;
  }
  EXPECT_EQ(term->stats(sheet.x).candidate_pairs, reachable);
  // The layers and the ball lie within millimetres, yet a fifth of the pairs can be dropped.
  EXPECT_LT(5 * reachable, 4 * static_cast<int>(found.size()))
      << reachable << " of " << found.size() << " pairs can come within the thickness";
}

TEST(GatherRegion, AStepOutsideTheRegionGathersAgainAndStillStopsAtTheGround) {
  const FoldedSheet sheet = folded_sheet();
  const auto term = contact_for(sheet);
  term->update(sheet.x);
  const std::int64_t first = term->stats(sheet.x).gathers;
  // Down by 1 cm: the lower layer, 1.5 mm up, may take 90% of its gap (CCD's minimum
  // separation 0.1), so the bound is 0.9 * 1.5 / 10.
  const Eigen::VectorXd down =
      Eigen::Vector3d(0.0, -0.01, 0.0).replicate(sheet.model.particle_count(), 1);
  EXPECT_NEAR(term->max_step(sheet.x, down), 0.9 * 1.5e-3 / 0.01, 1e-12);
  EXPECT_EQ(term->stats(sheet.x).gathers, first + 1);
  // Half of that step again is inside the new region: no gather.
  EXPECT_NEAR(term->max_step(sheet.x, 0.5 * down), 0.9 * 1.5e-3 / 0.005, 1e-12);
  EXPECT_EQ(term->stats(sheet.x).gathers, first + 1);
}

TEST(GatherRegion, ClothRestingOnABallRunsTheBroadPhaseRarely) {
  // A cotton sheet dropped onto a ball on the ground, then 10 steps resting on it.
  GridClothOptions grid{.cells = 8, .size = 0.4, .gravity = 9.81};
  grid.height = 0.13;
  grid.material = ClothMaterial{};
  ClothDesc desc = make_grid_cloth(grid);
  for (ParticleDesc& p : desc.particles) {
    p.position.x() -= 0.2;
    p.position.z() -= 0.2;
    p.pinned = false;
  }
  SimulationOptions options{find_integrator("implicit-multigrid")->defaults, 0};
  set_tolerance(options.integrator, 1e-4);
  auto sim = ClothSimulator::create(desc, options);
  ASSERT_TRUE(sim);
  TriangleMesh ball = collider_surface(SphereShape{0.1}, 3);
  auto contact =
      ContactTerm::create(std::make_shared<const ClothModel>(sim->model()), {.thickness = 2e-3},
                          {.meshes = {ball}, .ground_height = -0.1});
  ASSERT_TRUE(contact);
  ASSERT_TRUE(sim->add_energy_term(*contact));
  for (int frame = 0; frame < 20; ++frame) ASSERT_TRUE(sim->step(1.0 / 30.0));  // settles
  const std::int64_t before = (*contact)->stats(sim->state().positions).gathers;
  int newton = 0;
  for (int frame = 0; frame < 10; ++frame) {
    const auto report = sim->step(1.0 / 30.0);
    ASSERT_TRUE(report);
    newton += report->newton_iterations;
  }
  const std::int64_t gathers = (*contact)->stats(sim->state().positions).gathers - before;
  // Frictionless, the sheet keeps sliding off the ball a little every step, so a step may
  // gather once; its Newton iterations once gathered twice each.
  EXPECT_GT(newton, 20);
  EXPECT_LE(gathers, 10) << gathers << " gathers in " << newton << " Newton iterations";
}

}  // namespace
}  // namespace animkit
