#include "animkit/trajectory/lab_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace animkit {
namespace {

TEST(LabShapes, CountsAndPlaneAreTheLabs) {
  const std::pair<LabShape, std::size_t> expected[] = {{LabShape::circle, 150},
                                                       {LabShape::square, 150},
                                                       {LabShape::heart, 150},
                                                       {LabShape::triangle, 150},
                                                       {LabShape::star, 400}};
  for (const auto& [shape, count] : expected) {
    const auto targets = lab_shape_targets(shape);
    EXPECT_EQ(targets.size(), count) << to_string(shape);
    for (const Vec3& t : targets) EXPECT_EQ(t.y(), 0.0);
  }
}

TEST(LabShapes, CircleHasRadius06) {
  const auto targets = lab_shape_targets(LabShape::circle);
  for (const Vec3& t : targets) EXPECT_NEAR(t.norm(), 0.6, 1e-15);
  EXPECT_NEAR(targets[0].x(), 0.6, 1e-15);
}

TEST(LabShapes, SquareHasSide04AndStartsAtACorner) {
  const auto targets = lab_shape_targets(LabShape::square);
  EXPECT_EQ(targets[0], Vec3(-0.2, 0.0, 0.2));
  for (const Vec3& t : targets) {
    EXPECT_LE(std::abs(t.x()), 0.2 + 1e-15);
    EXPECT_LE(std::abs(t.z()), 0.2 + 1e-15);
    // On the boundary: one coordinate at +-0.2.
    EXPECT_NEAR(std::max(std::abs(t.x()), std::abs(t.z())), 0.2, 1e-15);
  }
  // The lab's edge splits: 37, 38, 37, 38 points.
  EXPECT_EQ(targets[37], Vec3(0.2, 0.0, 0.2));
  EXPECT_EQ(targets[75], Vec3(0.2, 0.0, -0.2));
  EXPECT_EQ(targets[112], Vec3(-0.2, 0.0, -0.2));
}

TEST(LabShapes, HeartFollowsItsPolarEquation) {
  const auto targets = lab_shape_targets(LabShape::heart);
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const double t = 2.0 * std::numbers::pi * static_cast<double>(i) / 150.0;
    EXPECT_NEAR(targets[i].norm(), 0.5 * (1.0 - std::sin(t)), 1e-15);
  }
}

TEST(LabShapes, TriangleCorners) {
  const auto targets = lab_shape_targets(LabShape::triangle);
  EXPECT_EQ(targets[0], Vec3(0.0, 0.0, 0.0));
  EXPECT_EQ(targets[50], Vec3(0.5, 0.0, 0.0));
  EXPECT_EQ(targets[100], Vec3(0.0, 0.0, 0.5));
}

TEST(LabShapes, StarVisitsEverySecondPentagonVertex) {
  const auto targets = lab_shape_targets(LabShape::star);
  const int order[] = {4, 1, 3, 0, 2};
  for (int e = 0; e < 5; ++e) {
    const double t = 2.0 * std::numbers::pi * order[e] / 5.0;
    EXPECT_LT((targets[80 * e] - Vec3(0.4 * std::cos(t), 0.0, 0.4 * std::sin(t))).norm(), 1e-15);
  }
  for (const Vec3& p : targets) EXPECT_LE(p.norm(), 0.4 + 1e-15);
}

TEST(LabShapes, NamesRoundTrip) {
  for (LabShape shape : all_lab_shapes()) EXPECT_EQ(parse_lab_shape(to_string(shape)), shape);
  EXPECT_EQ(parse_lab_shape("hexagon"), std::nullopt);
}

}  // namespace
}  // namespace animkit
