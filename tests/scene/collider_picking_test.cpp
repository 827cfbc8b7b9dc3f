#include "animkit/scene/collider_picking.h"

#include <gtest/gtest.h>

#include <cmath>

namespace animkit {
namespace {

Collider ball(const char* name, const Vec3& centre, double radius) {
  ColliderDesc desc{.name = name,
                    .shape = SphereShape{radius},
                    .motion = ScriptedMotion{.initial = {centre, Quat::Identity()}}};
  return *Collider::create(desc);
}

TEST(ColliderPicking, TheRayGrabsTheFirstSurfaceItMeets) {
  // Two balls on the z axis, seen from +z: the nearer one is grabbed, on its near side.
  const std::vector<Collider> colliders = {ball("far", Vec3(0, 0, -3), 0.5),
                                           ball("near", Vec3(0, 0, 0), 0.5)};
  const Ray ray{Vec3(0.1, 0.05, 5.0), Vec3(0, 0, -1)};
  const auto grab = pick_collider(colliders, ray);
  ASSERT_TRUE(grab.has_value());
  EXPECT_EQ(grab->collider, 1);
  // The tessellated sphere lies inside the true one, by under 1% of the radius.
  EXPECT_NEAR(grab->point.norm(), 0.5, 0.005);
  EXPECT_GT(grab->point.z(), 0.0);
  EXPECT_NEAR(grab->distance, 5.0 - grab->point.z(), 1e-12);
  EXPECT_EQ(grab->pose.position, Vec3::Zero());
  // A ray beside both balls meets nothing, and neither does one pointing away from them.
  EXPECT_FALSE(pick_collider(colliders, {Vec3(0.6, 0, 5), Vec3(0, 0, -1)}).has_value());
  EXPECT_FALSE(pick_collider(colliders, {Vec3(0, 0, 5), Vec3(0, 0, 1)}).has_value());
  // From inside the near ball, its own far side comes first.
  const auto inside = pick_collider(colliders, {Vec3(0, 0, 0), Vec3(0, 0, -1)});
  ASSERT_TRUE(inside.has_value());
  EXPECT_EQ(inside->collider, 1);
  EXPECT_NEAR(inside->distance, 0.5, 0.005);
}

TEST(ColliderPicking, PlanesAreNotGrabbed) {
  ColliderDesc floor{.name = "floor", .shape = PlaneShape{2.0}};
  const std::vector<Collider> colliders = {*Collider::create(floor)};
  EXPECT_FALSE(pick_collider(colliders, {Vec3(0, 1, 0), Vec3(0, -1, 0)}).has_value());
}

TEST(ColliderPicking, TheDraggedPoseKeepsTheGrabbedPointUnderTheCursor) {
  ColliderGrab grab;
  grab.point = Vec3(0.2, 1.0, 0.3);
  grab.pose.position = Vec3(0.0, 1.0, 0.0);
  grab.pose.rotation = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 1, 0).normalized()));
  const Vec3 local = grab.pose.to_local(grab.point);
  const Vec3 cursor(-0.4, 1.5, 0.9);
  const RigidPose moved = dragged_pose(grab, cursor);
  EXPECT_LT((moved.to_world(local) - cursor).norm(), 1e-14);
  EXPECT_EQ(moved.rotation.coeffs(), grab.pose.rotation.coeffs());
}

}  // namespace
}  // namespace animkit
