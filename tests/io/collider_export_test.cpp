#include "animkit/io/collider_export.h"

#include <gtest/gtest.h>

#include <sstream>

#include "../support/temp_files.h"
#include "animkit/io/point_cache.h"

namespace animkit {
namespace {

std::vector<Collider> scene_colliders() {
  ColliderDesc floor{.name = "floor", .shape = PlaneShape{4.0}};
  ColliderDesc ball{.name = "ball",
                    .shape = SphereShape{0.3},
                    .motion = ScriptedMotion{.initial = {Vec3(0, 1, 0), Quat::Identity()},
                                             .linear_velocity = Vec3(0, -0.5, 0)},
                    .tessellation = 1};
  ColliderDesc post{.name = "post", .shape = CapsuleShape{0.1, 0.4}, .tessellation = 0};
  return {*Collider::create(floor), *Collider::create(ball), *Collider::create(post)};
}

struct ParsedObj {
  std::vector<std::string> objects;
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> faces;  // 1-based, as written
};

ParsedObj parse_obj(const std::string& text) {
  ParsedObj obj;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream fields(line);
    std::string kind;
    fields >> kind;
    if (kind == "o") {
      std::string name;
      fields >> name;
      obj.objects.push_back(name);
    } else if (kind == "v") {
      Vec3 v;
      fields >> v.x() >> v.y() >> v.z();
      obj.vertices.push_back(v);
    } else if (kind == "f") {
      std::array<int, 3> f;
      fields >> f[0] >> f[1] >> f[2];
      obj.faces.push_back(f);
    }
  }
  return obj;
}

TEST(ColliderExport, ObjHoldsEveryColliderInItsPose) {
  const std::vector<Collider> colliders = scene_colliders();
  const ParsedObj obj = parse_obj(colliders_obj(colliders, 1.0));
  EXPECT_EQ(obj.objects, (std::vector<std::string>{"floor", "ball", "post"}));
  std::size_t vertices = 0, faces = 0;
  for (const Collider& c : colliders) {
    vertices += c.model().surface.vertices.size();
    faces += c.model().surface.triangles.size();
  }
  ASSERT_EQ(obj.vertices.size(), vertices);
  EXPECT_EQ(static_cast<int>(vertices), collider_point_count(colliders));
  ASSERT_EQ(obj.faces.size(), faces);
  EXPECT_EQ(obj.faces.front(), (std::array<int, 3>{1, 2, 3}));  // the floor's square
  for (const auto& f : obj.faces) {
    for (int i : f) {
      EXPECT_GE(i, 1);
      EXPECT_LE(i, static_cast<int>(vertices));
    }
  }
  // The ball (after the floor's 4 vertices) has fallen 0.5 m by t = 1 s.
  const Vec3 ball_vertex = obj.vertices[4];
  EXPECT_NEAR((ball_vertex - Vec3(0, 0.5, 0)).norm(), 0.3, 1e-8);
  // Vertex order is the PC2 frame's point order.
  const Eigen::VectorXd frame = collider_points(colliders, 1.0);
  for (std::size_t i = 0; i < obj.vertices.size(); ++i) {
    EXPECT_LT((obj.vertices[i] - Vec3(frame.segment<3>(3 * static_cast<Eigen::Index>(i)))).norm(),
              1e-8);
  }
}

TEST(ColliderExport, Pc2HoldsOneFramePerTime) {
  const std::vector<Collider> colliders = scene_colliders();
  const auto dir = testing_support::fresh_dir("colliders_pc2");
  const int points = collider_point_count(colliders);
  {
    auto writer = Pc2Writer::open(dir / "colliders.pc2", points);
    ASSERT_TRUE(writer);
    for (int frame = 0; frame < 12; ++frame) {
      ASSERT_TRUE(writer->add_frame(collider_points(colliders, frame / 24.0)));
    }
    ASSERT_TRUE(writer->finish());
  }
  const auto cache = read_pc2(dir / "colliders.pc2");
  ASSERT_TRUE(cache) << cache.error().message;
  EXPECT_EQ(cache->points, points);
  ASSERT_EQ(cache->frames.size(), 12u);
  // The ball's first vertex moves down 0.5 m/s; the floor stays put.
  const std::size_t ball_y = 3 * 4 + 1;
  EXPECT_NEAR(cache->frames[11][ball_y] - cache->frames[0][ball_y], -0.5 * 11 / 24.0, 1e-6);
  EXPECT_EQ(cache->frames[11][1], cache->frames[0][1]);
}

}  // namespace
}  // namespace animkit
