#include "animkit/collision/collider.h"

#include <gtest/gtest.h>

#include <limits>
#include <numbers>

#include "shared_constants.h"

namespace animkit {
namespace {

using testing_support::kNaN;

ColliderDesc ball() {
  ColliderDesc d;
  d.name = "ball";
  d.shape = SphereShape{0.5};
  return d;
}

std::string problem(const ColliderDesc& d) {
  const auto e = d.validate();
  return e ? e->message : "";
}

TEST(ColliderDesc, ValidateNamesTheFirstProblem) {
  EXPECT_EQ(problem(ball()), "");
  ColliderDesc d = ball();
  d.shape = SphereShape{-1};
  EXPECT_EQ(problem(d), "collider 'ball': radius must be > 0, got -1");
  d.shape = SphereShape{kNaN};
  EXPECT_EQ(problem(d), "collider 'ball': radius must be > 0, got nan");
  d.shape = SphereShape{std::numeric_limits<double>::infinity()};
  EXPECT_EQ(problem(d), "collider 'ball': radius must be at most 1e+06, got inf");
  d.shape = BoxShape{Vec3(1, 0, 1)};
  EXPECT_EQ(problem(d),
            "collider 'ball': half extents must be > 0 and at most 1e+06, got (1, 0, 1)");
  d.shape = CapsuleShape{0.2, -0.5};
  EXPECT_EQ(problem(d), "collider 'ball': half length must be > 0, got -0.5");
  d.shape = PlaneShape{0.0};
  EXPECT_EQ(problem(d), "collider 'ball': display size must be > 0, got 0");
  TriangleMesh flat{{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 2}}};
  d.shape = MeshShape{flat};
  EXPECT_EQ(problem(d), "collider 'ball': mesh triangle 0 has zero area");

  d = ball();
  d.motion = ScriptedMotion{.initial = {Vec3::Zero(), Quat(0, 0, 0, 0)}};
  EXPECT_EQ(problem(d), "collider 'ball': initial rotation is the zero quaternion");
  d.motion = KeyframedMotion{
      {{1.0, Vec3::Zero(), Quat::Identity()}, {0.5, Vec3::Zero(), Quat::Identity()}}};
  EXPECT_EQ(problem(d), "collider 'ball': keyframe 1 is at 0.5 s, not after keyframe 0 at 1 s");

  d = ball();
  d.friction = -0.1;
  EXPECT_EQ(problem(d), "collider 'ball': friction must be between 0 and 10, got -0.1");
  d.friction = kNaN;
  EXPECT_EQ(problem(d), "collider 'ball': friction must be between 0 and 10, got nan");
  d.friction = 1e300;
  EXPECT_EQ(problem(d), "collider 'ball': friction must be between 0 and 10, got 1e+300");
  d = ball();
  d.shape = MeshShape{TriangleMesh{{{0, 0, 0}, {1, 0, 0}, {0, 1e300, 0}}, {{0, 1, 2}}}};
  EXPECT_EQ(problem(d),
            "collider 'ball': mesh vertex 2 must have each coordinate between -1e+06 and 1e+06, "
            "got (0, 1e+300, 0)");
  d = ball();
  d.motion = ScriptedMotion{.linear_velocity = Vec3(1e300, 0, 0)};
  EXPECT_EQ(problem(d),
            "collider 'ball': linear velocity must have each coordinate between -1e+06 and 1e+06, "
            "got (1e+300, 0, 0)");
  d = ball();
  d.tessellation = 7;
  EXPECT_EQ(problem(d), "collider 'ball': tessellation must be between 0 and 6, got 7");

  d = ball();
  d.name = "";
  EXPECT_EQ(problem(d), "a collider has an empty name");
  d.name = "a\nb";
  EXPECT_EQ(problem(d), "collider 'a\\nb' has a control character in its name");
}

TEST(ColliderDesc, NamesMustDiffer) {
  ColliderDesc floor;
  floor.name = "floor";
  floor.shape = PlaneShape{};
  EXPECT_FALSE(validate_colliders({ball(), floor}));
  EXPECT_EQ(validate_colliders({ball(), floor, ball()})->message, "two colliders are named 'ball'");
}

// Many small spheres from a short scene file: refused before any surface is made.
TEST(ColliderDesc, TheCollidersSurfacesAreBoundedTogether) {
  std::vector<ColliderDesc> pebbles(1600, ball());
  for (std::size_t i = 0; i < pebbles.size(); ++i) {
    pebbles[i].name = "pebble " + std::to_string(i);
    pebbles[i].tessellation = 4;  // 5120 triangles each
  }
  EXPECT_EQ(validate_colliders(pebbles)->message,
            "the colliders' surfaces would have 8192000 triangles, more than the 2000000 a "
            "scene may have (lower their tessellation or use fewer colliders)");
  pebbles.resize(390);  // 1,996,800 triangles
  EXPECT_FALSE(validate_colliders(pebbles));
}

TEST(Collider, CreateRefusesAnInvalidDescription) {
  ColliderDesc d = ball();
  d.friction = -1;
  const auto c = Collider::create(d);
  ASSERT_FALSE(c);
  EXPECT_EQ(c.error().message, "collider 'ball': friction must be between 0 and 10, got -1");
}

TEST(Collider, WorldVerticesFollowThePose) {
  ColliderDesc d = ball();
  d.shape = BoxShape{Vec3(0.2, 0.4, 0.6)};
  d.tessellation = 1;
  d.motion = ScriptedMotion{.initial = {Vec3(1, 2, 3), Quat::Identity()},
                            .linear_velocity = Vec3(0, -1, 0),
                            .angular_velocity = Vec3(0, std::numbers::pi, 0)};
  auto c = Collider::create(d);
  ASSERT_TRUE(c) << c.error().message;
  const ColliderModel& model = c->model();
  EXPECT_EQ(model.surface.triangles.size(), 48u);
  EXPECT_EQ(2 * model.edges.size(), 3 * model.surface.triangles.size());
  EXPECT_EQ(c->world_vertices().size(), model.surface.vertices.size());
  for (std::size_t i = 0; i < model.surface.vertices.size(); ++i) {
    EXPECT_TRUE(c->world_vertices()[i].isApprox(model.surface.vertices[i] + Vec3(1, 2, 3)));
  }
  // Half a second later: moved down 0.5 m and turned a quarter turn about +y.
  std::vector<Vec3> later;
  c->world_vertices_at(0.5, later);
  EXPECT_EQ(c->time(), 0.0);  // a query, not a move
  c->set_time(0.5);
  EXPECT_EQ(c->world_vertices(), later);
  for (std::size_t i = 0; i < later.size(); ++i) {
    const Vec3& l = model.surface.vertices[i];
    EXPECT_LT((later[i] - Vec3(1 + l.z(), 1.5 + l.y(), 3 - l.x())).norm(), 1e-14);
  }
  // Copies share the model and keep their own state.
  Collider copy = *c;
  EXPECT_EQ(copy.shared_model().get(), c->shared_model().get());
  copy.set_time(1.0);
  EXPECT_EQ(c->time(), 0.5);
}

TEST(Collider, SurfacePointVelocityMatchesVertexMotion) {
  ColliderDesc d = ball();
  d.motion = KeyframedMotion{{{0.0, Vec3(0, 1, 0), Quat::Identity()},
                              {1.0, Vec3(1, 1, 0), Quat(Eigen::AngleAxisd(1.0, Vec3::UnitX()))}}};
  auto c = Collider::create(d, 0.4);
  ASSERT_TRUE(c);
  const double h = 1e-6;
  std::vector<Vec3> before, after;
  c->world_vertices_at(0.4 - h, before);
  c->world_vertices_at(0.4 + h, after);
  for (std::size_t i = 0; i < before.size(); ++i) {
    const Vec3 difference = (after[i] - before[i]) / (2 * h);
    EXPECT_LT((c->point_velocity(c->world_vertices()[i]) - difference).norm(), 1e-7);
  }
}

TEST(Collider, InsideIsTestedInTheCollidersCurrentPose) {
  ColliderDesc table;
  table.name = "table";
  table.shape = BoxShape{Vec3(1.0, 0.05, 0.5)};
  table.motion = ScriptedMotion{.initial = {Vec3(0, 1, 0), Quat::Identity()},
                                .linear_velocity = Vec3(1, 0, 0)};
  auto c = Collider::create(table);
  ASSERT_TRUE(c);
  EXPECT_TRUE(c->inside(Vec3(0.9, 1.0, 0.0)));
  EXPECT_FALSE(c->inside(Vec3(0.9, 1.1, 0.0)));
  c->set_time(1.0);
  EXPECT_TRUE(c->inside(Vec3(1.9, 1.0, 0.0)));
  EXPECT_FALSE(c->inside(Vec3(-0.5, 1.0, 0.0)));

  // A tilted ground plane is a half-space.
  ColliderDesc ground;
  ground.name = "ground";
  ground.shape = PlaneShape{};
  ground.motion = ScriptedMotion{
      .initial = {Vec3::Zero(), Quat(Eigen::AngleAxisd(std::numbers::pi / 4, Vec3::UnitZ()))}};
  auto g = Collider::create(ground);
  ASSERT_TRUE(g);
  EXPECT_TRUE(g->is_half_space());
  EXPECT_FALSE(c->is_half_space());
  EXPECT_TRUE(g->inside(Vec3(1.0, 0.9, 0.0)));  // below the line y = x
  EXPECT_FALSE(g->inside(Vec3(1.0, 1.1, 0.0)));
  EXPECT_TRUE(g->inside(Vec3(50.0, 0.0, 80.0)));  // far beyond the drawn square

  // A mesh collider uses its winding number.
  ColliderDesc rock = ball();
  rock.name = "rock";
  rock.shape = MeshShape{c->model().surface};
  rock.motion = ScriptedMotion{.initial = {Vec3(0, 5, 0), Quat::Identity()}};
  auto r = Collider::create(rock);
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->inside(Vec3(0.5, 5.0, 0.2)));
  EXPECT_FALSE(r->inside(Vec3(0.5, 5.1, 0.2)));
  EXPECT_FALSE(r->inside(Vec3(0.0, 1.0, 0.0)));
}

TEST(Collider, FindsTheFirstParticleInside) {
  ColliderDesc table;
  table.name = "table";
  table.shape = BoxShape{Vec3(1.0, 0.05, 1.0)};
  table.motion = ScriptedMotion{.initial = {Vec3(0, 1, 0), Quat::Identity()}};
  std::vector<Collider> colliders = {*Collider::create(ball()), *Collider::create(table)};
  Eigen::VectorXd positions(9);
  positions << 0, 2, 0, 0.5, 1.02, 0.5, 0, 0.2, 0;
  EXPECT_EQ(find_particle_inside(positions, colliders)->message,
            "particle 1 starts inside collider 'table'");
  positions.segment<3>(3) = Vec3(0.5, 1.2, 0.5);
  EXPECT_EQ(find_particle_inside(positions, colliders)->message,
            "particle 2 starts inside collider 'ball'");
  positions.segment<3>(6) = Vec3(0, 0.6, 0);
  EXPECT_FALSE(find_particle_inside(positions, colliders));
}

}  // namespace
}  // namespace animkit
