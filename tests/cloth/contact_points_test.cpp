// Contact pairs' closest points (src/cloth/contact/contact_points.h, ContactTerm::
// contact_points): on random point-triangle and edge-edge configurations, including grazing
// and parallel ones, the points lie on their primitives, their distance is the classified
// distance the barrier uses, and no sampled pair of points on the primitives is closer; a
// sheet on the ground and a ball lists one point per active pair, each where it should be.
#include "../../src/cloth/contact/contact_points.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/contact.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/collision/collider_surface.h"
#include "animkit/collision/distance_type.h"

namespace animkit {
namespace {

Vec3 random_point(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return Vec3(u(rng), u(rng), u(rng));
}

TEST(ContactPoints, TheClosestPointOnATriangleIsNoFartherThanAnyOtherAndGivesTheDistance) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 p = random_point(rng), a = random_point(rng), b = random_point(rng),
               c = trial % 10 == 0 ? Vec3(a + 0.5 * (b - a)) : random_point(rng);  // degenerate
    const Vec3 q = closest_point_on_triangle(p, a, b, c);
    const double d2 = (q - p).squaredNorm();
    if (trial % 10 != 0) {
      EXPECT_NEAR(d2, point_triangle_distance_squared(p, a, b, c), 1e-12) << trial;
    }
    // q is on the triangle: its barycentric coordinates are in [0, 1] and sum to 1.
    for (int k = 0; k < 50; ++k) {
      double u = unit(rng), v = unit(rng);
      if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
      const Vec3 s = a + u * (b - a) + v * (c - a);
      ASSERT_LE(d2, (s - p).squaredNorm() + 1e-12) << trial;
    }
  }
}

TEST(ContactPoints, TheClosestPointsOfSegmentsAreNoFartherThanAnyOthersAndGiveTheDistance) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 a0 = random_point(rng), a1 = random_point(rng);
    Vec3 b0 = random_point(rng), b1 = random_point(rng);
    if (trial % 4 == 0) {  // parallel, overlapping or not
      const Vec3 shift = random_point(rng);
      b0 = a0 + shift + unit(rng) * (a1 - a0);
      b1 = b0 + (0.2 + unit(rng)) * (a1 - a0);
    }
    const auto [qa, qb] = closest_points_of_segments(a0, a1, b0, b1);
    const double d2 = (qa - qb).squaredNorm();
    EXPECT_NEAR(d2, edge_edge_distance_squared(a0, a1, b0, b1), 1e-12) << trial;
    // Each point on its segment.
    EXPECT_NEAR((qa - a0).norm() + (qa - a1).norm(), (a1 - a0).norm(), 1e-9) << trial;
    EXPECT_NEAR((qb - b0).norm() + (qb - b1).norm(), (b1 - b0).norm(), 1e-9) << trial;
    for (int k = 0; k < 50; ++k) {
      const Vec3 sa = a0 + unit(rng) * (a1 - a0), sb = b0 + unit(rng) * (b1 - b0);
      ASSERT_LE(d2, (sa - sb).squaredNorm() + 1e-12) << trial;
    }
  }
}

TEST(ContactPoints, ASheetOnTheGroundAndABallListsEveryActivePairWhereItTouches) {
  // A 0.6 m sheet 1.2 mm above the ground, a ball just touching its middle from below...
  GridClothOptions grid{.cells = 6, .size = 0.6, .gravity = 9.81};
  grid.height = 0.0012;
  grid.material = ClothMaterial{};
  ClothDesc desc = make_grid_cloth(grid);
  for (ParticleDesc& p : desc.particles) p.position.x() -= 0.3;
  auto sim = ClothSimulator::create(desc, {});
  ASSERT_TRUE(sim) << sim.error().message;
  TriangleMesh ball = collider_surface(SphereShape{0.05}, 3);
  for (Vec3& v : ball.vertices) v += Vec3(0.0, 0.0012 + 0.0505, 0.0);  // ...and one above it
  auto contact = ContactTerm::create(std::make_shared<const ClothModel>(sim->model()),
                                     {.thickness = 2e-3}, {.meshes = {ball}, .ground_height = 0.0});
  ASSERT_TRUE(contact) << contact.error().message;
  const Eigen::VectorXd& x = sim->state().positions;
  (*contact)->update(x);
  std::vector<ContactPoint> points;
  (*contact)->contact_points(x, points);
  ASSERT_EQ(static_cast<int>(points.size()), (*contact)->stats(x).active_pairs);
  int ground = 0, collider = 0;
  for (const ContactPoint& p : points) {
    EXPECT_NEAR((p.cloth - p.other).norm(), p.distance, 1e-12);
    EXPECT_LT(p.distance, 2e-3);
    EXPECT_NEAR(p.cloth.y(), 0.0012, 1e-12);  // on the flat sheet
    if (p.with == ContactPoint::With::ground) {
      ++ground;
      EXPECT_EQ(p.other.y(), 0.0);
      EXPECT_NEAR(p.distance, 0.0012, 1e-12);
    } else {
      ASSERT_EQ(p.with, ContactPoint::With::collider);  // a flat sheet does not touch itself
      ++collider;
      EXPECT_GT(p.other.y(), p.cloth.y());  // the ball's side
      EXPECT_NEAR((p.other - Vec3(0.0, 0.0517, 0.0)).norm(), 0.05, 1e-3);
    }
  }
  EXPECT_EQ(ground, sim->model().particle_count());  // every particle is 1.2 mm up
  EXPECT_GT(collider, 0);
}

}  // namespace
}  // namespace animkit
