#include "animkit/scene/collider_drawing.h"

#include <gtest/gtest.h>

namespace animkit {
namespace {

std::vector<Collider> two_colliders() {
  ColliderDesc floor{.name = "floor", .shape = PlaneShape{2.0}};
  ColliderDesc ball{.name = "ball",
                    .shape = SphereShape{0.5},
                    .motion = ScriptedMotion{.initial = {Vec3(0, 1, 0), Quat::Identity()},
                                             .linear_velocity = Vec3(1, 0, 0)},
                    .tessellation = 2};
  return {*Collider::create(floor), *Collider::create(ball)};
}

TEST(ColliderDrawing, EverySurfaceTriangleInItsPoseAndColour) {
  const std::vector<Collider> colliders = two_colliders();
  DrawList list;
  describe_colliders(list, colliders, 2.0);
  const std::size_t triangles = 2 + 320;
  ASSERT_EQ(list.triangles.size(), 3 * triangles);
  EXPECT_TRUE(list.lines.empty());
  for (const LitVertex& v : list.triangles) {
    EXPECT_EQ(v.front.b, palette::collider.b);
    EXPECT_EQ(v.back.r, palette::collider.r);
    EXPECT_NEAR(v.normal.norm(), 1.0f, 1e-5f);
  }
  // The floor's square faces up; the ball, moved to (2, 1, 0), has its radial normals.
  for (int k = 0; k < 6; ++k) EXPECT_EQ(list.triangles[k].normal, Vec3f(0, 1, 0));
  for (std::size_t k = 6; k < list.triangles.size(); ++k) {
    const Vec3f radial = (list.triangles[k].position - Vec3f(2, 1, 0)) / 0.5f;
    EXPECT_NEAR(radial.norm(), 1.0f, 1e-5f);
    EXPECT_LT((list.triangles[k].normal - radial).norm(), 1e-5f);
  }
  const Eigen::AlignedBox3d bounds = list.bounds();
  EXPECT_NEAR(bounds.max().x(), 2.5, 1e-6);
}

TEST(ColliderDrawing, PlanesCanBeLeftOut) {
  DrawList list;
  describe_colliders(list, two_colliders(), 0.0, {.planes = false});
  EXPECT_EQ(list.triangles.size(), 3u * 320u);
}

}  // namespace
}  // namespace animkit
