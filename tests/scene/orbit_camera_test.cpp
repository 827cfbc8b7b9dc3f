#include "animkit/scene/orbit_camera.h"

#include <gtest/gtest.h>

namespace animkit {
namespace {

TEST(OrbitCamera, RayThroughTheProjectionOfAPointPassesThroughIt) {
  OrbitCamera camera;
  camera.focus = Vec3(0.3, 0.5, -0.2);
  camera.yaw = -1.1;
  camera.pitch = 0.4;
  camera.distance = 5.0;
  for (const Vec3& p : {Vec3(0.0, 0.0, 0.0), Vec3(1.0, 2.0, -0.5), Vec3(-0.7, 0.1, 0.9)}) {
    const auto pixel = camera.project(p, 640.0, 480.0);
    ASSERT_TRUE(pixel.has_value());
    const Ray ray = camera.ray_through_pixel(pixel->x(), pixel->y(), 640.0, 480.0);
    const Vec3 to_point = p - ray.origin;
    const double off_ray = (to_point - to_point.dot(ray.direction) * ray.direction).norm();
    EXPECT_LT(off_ray, 1e-9);
    EXPECT_NEAR(ray.direction.norm(), 1.0, 1e-12);
  }
}

TEST(OrbitCamera, FocusProjectsToTheCentreAndPointsBehindTheEyeDoNot) {
  OrbitCamera camera;
  const auto centre = camera.project(camera.focus, 800.0, 600.0);
  ASSERT_TRUE(centre.has_value());
  EXPECT_NEAR(centre->x(), 400.0, 1e-9);
  EXPECT_NEAR(centre->y(), 300.0, 1e-9);
  const Vec3 behind = camera.eye() + (camera.eye() - camera.focus);
  EXPECT_FALSE(camera.project(behind, 800.0, 600.0).has_value());
}

TEST(OrbitCamera, FramingFitsEveryCornerInsideTheMargin) {
  Eigen::AlignedBox3d box(Vec3(-1.0, 0.0, -0.5), Vec3(2.0, 1.7, 0.5));
  for (double aspect : {0.5, 4.0 / 3.0, 2.5}) {
    const OrbitCamera camera = OrbitCamera::framing(box, aspect, 0.5, 0.9, 0.1);
    const double height = 600.0, width = aspect * height;
    double min_x = width, max_x = 0.0, min_y = height, max_y = 0.0;
    for (int k = 0; k < 8; ++k) {
      const auto p = camera.project(box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k)),
                                    width, height);
      ASSERT_TRUE(p.has_value());
      min_x = std::min(min_x, p->x());
      max_x = std::max(max_x, p->x());
      min_y = std::min(min_y, p->y());
      max_y = std::max(max_y, p->y());
    }
    // Inside the picture with the margin, and touching the margin on at least one side (the
    // tightest fit, not merely a fit).
    const double mx = width * 0.1 / 1.2, my = height * 0.1 / 1.2;
    EXPECT_GE(min_x, mx - 1e-6);
    EXPECT_LE(max_x, width - mx + 1e-6);
    EXPECT_GE(min_y, my - 1e-6);
    EXPECT_LE(max_y, height - my + 1e-6);
    const double slack =
        std::min({min_x - mx, width - mx - max_x, min_y - my, height - my - max_y});
    EXPECT_LT(slack, 0.05 * height) << "aspect " << aspect;
  }
}

TEST(OrbitCamera, OrbitClampsPitchAndZoomClampsDistance) {
  OrbitCamera camera;
  camera.orbit(0.3, 10.0);
  EXPECT_LT(camera.pitch, 1.5708);
  camera.zoom(1e-9);
  EXPECT_GE(camera.distance, 1e-3);
}

TEST(OrbitCamera, PanMovesThePointUnderTheCursorWithIt) {
  OrbitCamera camera;
  const auto before = camera.project(Vec3::Zero(), 800.0, 600.0);
  camera.pan(40.0, -25.0, 600.0);
  const auto after = camera.project(Vec3::Zero(), 800.0, 600.0);
  ASSERT_TRUE(before && after);
  // A point at the focus depth moves exactly with the cursor; the origin is near it.
  EXPECT_NEAR(after->x() - before->x(), 40.0, 4.0);
  EXPECT_NEAR(after->y() - before->y(), -25.0, 4.0);
}

TEST(OrbitCamera, RayMeetsTheDrawingPlane) {
  const Ray down{Vec3(0.0, 2.0, 0.0), Vec3(0.6, -0.8, 0.0)};
  const auto hit = intersect_horizontal_plane(down, 0.0);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->x(), 1.5, 1e-12);
  EXPECT_NEAR(hit->y(), 0.0, 1e-12);
  const Ray up{Vec3(0.0, 2.0, 0.0), Vec3(0.0, 1.0, 0.0)};
  EXPECT_FALSE(intersect_horizontal_plane(up, 0.0).has_value());
  const Ray level{Vec3(0.0, 2.0, 0.0), Vec3(1.0, 0.0, 0.0)};
  EXPECT_FALSE(intersect_horizontal_plane(level, 0.0).has_value());
}

}  // namespace
}  // namespace animkit
