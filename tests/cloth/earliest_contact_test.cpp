// The step bound over gathered pairs (src/cloth/contact/contact_candidates.h): a pair that comes
// within the contact distance on the move bounds it, a pair whose primitives stay farther apart
// than that does not, however close it passes relative to its start; a pair whose vertices
// move too little to close its gap is passed over when its distance at the start is known.
#include "../../src/cloth/contact/contact_candidates.h"

#include "../../src/cloth/contact/contact_pair.h"
#include "animkit/cloth/contact.h"

#include <gtest/gtest.h>

#include <array>
#include <utility>
#include <vector>

namespace animkit {
namespace {

// One cloth triangle at height 0 and one obstacle triangle far to its side, 1 m wide.
struct Scene {
  ContactGeometry geometry;
  Eigen::VectorXd cloth;
};

Scene make_scene(double obstacle_height) {
  ClothModel model;
  model.mass = {1.0, 1.0, 1.0};
  model.pinned = {0, 0, 0};
  model.triangles = {{0, 1, 2}};
  TriangleMesh obstacle;
  obstacle.vertices = {Vec3(2.0, obstacle_height, -0.5), Vec3(3.0, obstacle_height, -0.5),
                       Vec3(2.5, obstacle_height, 0.5)};
  obstacle.triangles = {{0, 1, 2}};
  Scene scene{build_contact_geometry(model, {obstacle}, false).value(), Eigen::VectorXd(9)};
  scene.cloth << 0.0, 0.0, -0.1, 0.1, 0.0, -0.1, 0.05, 0.0, 0.1;
  return scene;
}

// The bound on moving the cloth triangle 2.5 m along x, under (or over) the obstacle, with the
// pairs gathered generously so the pair is in the list either way.
double bound_for(double obstacle_height, double reach) {
  Scene scene = make_scene(obstacle_height);
  Eigen::VectorXd step = Eigen::VectorXd::Zero(9);
  for (int v = 0; v < 3; ++v) step[3 * v] = 2.5;
  ContactPairFinder finder;
  std::vector<ContactPair> pairs;
  EXPECT_TRUE(finder.gather(scene.geometry, scene.cloth, &step, 1.0, std::nullopt, pairs));
  EXPECT_FALSE(pairs.empty());
  // Half its start distance: CCD keeps every pair above half of where it started.
  return earliest_contact(scene.geometry, pairs, scene.cloth, step, 0.0, reach, 0.5);
}

TEST(EarliestContact, APairPassingBeyondTheContactDistanceDoesNotBoundTheStep) {
  // 0.3 m apart at the closest: under half the 2 m start distance, beyond the 0.1 m reach.
  EXPECT_EQ(bound_for(0.3, 0.1), 1.0);
}

TEST(EarliestContact, APairPassingWithinTheContactDistanceBoundsTheStep) {
  // The same pass with a reach of 0.5 m: the pair comes within it, so CCD keeps it at half its
  // start distance, and the step stops before the triangles meet.
  const double bound = bound_for(0.3, 0.5);
  EXPECT_GT(bound, 0.0);
  EXPECT_LT(bound, 0.9);
}

TEST(EarliestContact, KnownStartDistancesPassOverOnlyPairsThatCannotCloseTheirGap) {
  const Scene scene = make_scene(0.3);
  Eigen::VectorXd step = Eigen::VectorXd::Zero(9);
  for (int v = 0; v < 3; ++v) step[3 * v] = 2.5;
  ContactPairFinder finder;
  std::vector<ContactPair> pairs;
  ASSERT_TRUE(finder.gather(scene.geometry, scene.cloth, &step, 1.0, std::nullopt, pairs));
  std::vector<double> distance2;
  for (const ContactPair& pair : pairs) {
    std::array<Vec3, 4> p;
    for (int i = 0; i < 4; ++i) {
      const int v = pair.vertices[i];
      p[i] = v < 3 ? Vec3(scene.cloth.segment<3>(3 * v))
                   : Vec3(scene.geometry.obstacle_positions.segment<3>(3 * (v - 3)));
    }
    distance2.push_back(contact_distance_squared(pair, p, 0.0));
  }
  const auto bound = [&](const Eigen::VectorXd& move, const std::vector<double>* floors) {
    return earliest_contact(scene.geometry, pairs, scene.cloth, move, 0.0, 0.5, 0.5, nullptr, {},
                            floors);
  };
  // The long pass comes within the reach: CCD bounds it, with the distances known or not.
  const double walked = bound(step, nullptr);
  EXPECT_LT(walked, 0.9);
  EXPECT_EQ(bound(step, &distance2), walked);
  // 0.8 m toward the obstacle, whose nearest point is about 1.9 m away: under half of that.
  const Eigen::VectorXd short_move = 0.32 * step;
  EXPECT_EQ(bound(short_move, &distance2), 1.0);
  EXPECT_EQ(bound(short_move, nullptr), 1.0);
  // The floors decide: told every pair starts 100 m apart, the long pass is not checked.
  const std::vector<double> far(pairs.size(), 100.0 * 100.0);
  EXPECT_EQ(bound(step, &far), 1.0);
}

// A cloth triangle `gap` above a wide obstacle triangle, dropped 1 m onto it: the bound, and
// the gap it leaves (the triangles are parallel, so every vertex keeps the same gap).
std::pair<double, double> drop_onto_obstacle(double gap, double reach) {
  ClothModel model;
  model.mass = {1.0, 1.0, 1.0};
  model.pinned = {0, 0, 0};
  model.triangles = {{0, 1, 2}};
  TriangleMesh floor_mesh;
  floor_mesh.vertices = {Vec3(-1.0, 0.0, -1.0), Vec3(1.0, 0.0, -1.0), Vec3(0.0, 0.0, 1.0)};
  floor_mesh.triangles = {{0, 1, 2}};
  const ContactGeometry geometry = build_contact_geometry(model, {floor_mesh}, false).value();
  Eigen::VectorXd cloth(9);
  cloth << 0.0, gap, 0.0, 0.1, gap, 0.0, 0.0, gap, 0.1;
  Eigen::VectorXd drop = Eigen::VectorXd::Zero(9);
  for (int v = 0; v < 3; ++v) drop[3 * v + 1] = -1.0;
  ContactPairFinder finder;
  std::vector<ContactPair> pairs;
  EXPECT_TRUE(finder.gather(geometry, cloth, &drop, reach, std::nullopt, pairs));
  const double bound = earliest_contact(geometry, pairs, cloth, drop, 0.0, reach, 0.1);
  return {bound, gap - bound};
}

TEST(EarliestContact, NoGapClosesBelowTheSmallestStartGap) {
  // A thickness of 2 mm: no gap may close below 2 nm, where computed distances of primitives
  // metres long are rounding. From 10 nm, a tenth of what lies above 2 nm is kept.
  const double reach = 2e-3, smallest = kMinStartGapFraction * reach;
  const auto [bound, left] = drop_onto_obstacle(1e-8, reach);
  EXPECT_GT(bound, 0.0);
  EXPECT_GE(left, smallest + 0.1 * (1e-8 - smallest) - 1e-15);
  // Already below it: no move toward the obstacle at all.
  EXPECT_EQ(drop_onto_obstacle(0.5 * smallest, reach).first, 0.0);
}

}  // namespace
}  // namespace animkit
