// Colliders moving inside the implicit step (src/cloth/contact/moving_obstacles.h): a sphere
// driven into a hanging cloth, a rotating tessellated sphere, a keyframed box, a collider moving
// away, a collider dragged by hand. Every frame is audited by an exact test that shares no code
// with the solver (CGAL, tests/support/intersection_audit.h), against every collider where its
// motion puts it at that time; pins hold; every step converges, which now also means every
// collider reached its pose at the step's end.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/contact.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/integrator_registry.h"
#include "animkit/io/collider_export.h"
#include "animkit/io/point_cache.h"
#include "intersection_audit.h"
#include "shared_constants.h"

namespace animkit {
namespace {

using testing_support::kFrame;

// A cotton sheet (side `size`, `cells` per side) in the plane y = height centred on the y axis,
// nothing pinned.
ClothDesc cotton_sheet(int cells, double size, double height) {
  GridClothOptions grid{.cells = cells, .size = size, .gravity = 9.81};
  grid.height = height;
  grid.material = ClothMaterial{};
  ClothDesc desc = make_grid_cloth(grid);
  for (ParticleDesc& p : desc.particles) {
    p.position.x() -= 0.5 * size;
    p.pinned = false;
  }
  return desc;
}

// The same sheet hanging in the plane z = 0 from its top edge (all pinned), from y = top down.
ClothDesc hanging_sheet(int cells, double size, double top) {
  ClothDesc desc = cotton_sheet(cells, size, 0.0);
  for (int i = 0; i <= cells; ++i) {
    for (int j = 0; j <= cells; ++j) {
      ParticleDesc& p = desc.particles[grid_index(cells, i, j)];
      p.position = Vec3(j * size / cells - 0.5 * size, top - i * size / cells, 0.0);
      p.pinned = i == 0;
    }
  }
  return desc;
}

SimulationOptions newton(int max_iterations = 500) {
  SimulationOptions options{find_integrator("implicit-multigrid")->defaults, 0};
  set_tolerance(options.integrator, 1e-4);
  std::get<NewtonSettings>(options.integrator).max_iterations = max_iterations;
  return options;
}

Collider collider(ColliderShape shape, ColliderMotion motion, int tessellation = 2) {
  auto c = Collider::create({.name = "c",
                             .shape = std::move(shape),
                             .motion = std::move(motion),
                             .tessellation = tessellation});
  EXPECT_TRUE(c) << c.error().message;
  return *c;
}

struct World {
  ClothSimulator sim;
  std::shared_ptr<ContactTerm> contact;
};

World make_world(const ClothDesc& desc, std::vector<Collider> colliders,
                 const SimulationOptions& options = newton()) {
  auto sim = ClothSimulator::create(desc, options);
  EXPECT_TRUE(sim) << sim.error().message;
  auto contact = ContactTerm::create(std::make_shared<const ClothModel>(sim->model()),
                                     {.thickness = 2e-3}, {.colliders = std::move(colliders)});
  EXPECT_TRUE(contact) << contact.error().message;
  EXPECT_TRUE(sim->add_energy_term(*contact));
  return {std::move(*sim), *contact};
}

TriangleMesh sheet_mesh(const ClothSimulator& sim) {
  TriangleMesh mesh;
  for (int i = 0; i < sim.model().particle_count(); ++i)
    mesh.vertices.push_back(sim.state().position(i));
  mesh.triangles = sim.model().triangles;
  return mesh;
}

// Collider c's surface where its motion puts it at time t: the audit's reference.
TriangleMesh surface_at(const Collider& c, double t) {
  TriangleMesh mesh;
  c.world_vertices_at(t, mesh.vertices);
  mesh.triangles = c.model().surface.triangles;
  return mesh;
}

// Runs `frames` frames; every one converged (so every collider reached its pose), the
// colliders where their motions put them, nothing intersecting, pins unmoved. Returns the
// Newton iterations of all the steps. `first`: the number of the first frame run. Without
// `converged`, a step may end at the iteration cap, but still with every collider at its pose.
int run_audited(World& w, int frames, int first = 1, bool converged = true) {
  const ClothState start = w.sim.state();
  int iterations = 0;
  for (int frame = first; frame < first + frames; ++frame) {
    const auto report = w.sim.step(kFrame);
    EXPECT_TRUE(report) << report.error().message;
    if (!report) return iterations;
    if (converged) {
      EXPECT_TRUE(report->converged) << "frame " << frame;
    }
    EXPECT_TRUE(w.contact->settled()) << "frame " << frame;
    iterations += report->newton_iterations;
    const double t = w.sim.state().time;
    EXPECT_NEAR(t, frame * kFrame, 1e-12);
    EXPECT_EQ(w.contact->collider_points(), collider_points(w.contact->colliders(), t));
    const TriangleMesh cloth = sheet_mesh(w.sim);
    for (const Collider& c : w.contact->colliders()) {
      EXPECT_FALSE(audit::meshes_intersect(cloth, surface_at(c, t))) << "frame " << frame;
    }
    EXPECT_EQ(audit::count_self_intersections(cloth), 0) << "frame " << frame;
    for (int i = 0; i < w.sim.model().particle_count(); ++i) {
      if (w.sim.model().pinned[i]) {
        EXPECT_EQ(w.sim.state().position(i), start.position(i));
      }
    }
  }
  return iterations;
}

// A sphere pushing a hanging sheet at 2 m/s (17 contact distances per frame). While the
// obstacles could only push the cloth along each pair's normal, frames 3 and 7 stalled
// millimetres short of the ball's pose within 500 Newton iterations (also with 4 substeps): the
// ball's vertices under one cloth triangle pushed it along different normals, tilting it into
// the ball. The pushed cloth is now carried with the ball when that goes further.
TEST(MovingObstacles, ASphereDrivenIntoAHangingClothPushesItAndNeverPassesThrough) {
  // 2 m/s: 3.3 cm per frame, 17 times the contact distance, into a cotton sheet at rest.
  const Vec3 velocity(0.0, 0.0, 2.0);
  World w = make_world(
      hanging_sheet(10, 0.6, 0.3),
      {collider(SphereShape{0.12}, ScriptedMotion{.initial = {.position = Vec3(0.0, -0.2, -0.15)},
                                                  .linear_velocity = velocity})});
  run_audited(w, 18);
  // The ball passed 0.3 m beyond the sheet's plane, low: the sheet swung away and over it.
  double furthest = 0.0;
  for (int i = 0; i < w.sim.model().particle_count(); ++i)
    furthest = std::max(furthest, w.sim.state().position(i).z());
  EXPECT_GT(furthest, 0.1);
}

// A hostile speed on a tiny cloth (5 x 5 particles, 25 cm apart): a ball at 100 m/s, 3.3 m per
// frame. With normal pushes only, it stalled short of its pose for all the Newton iterations a
// step allowed (0.49 m short after 300, 53 s a step); carried, it reaches its pose within a few.
// Against the ball's tessellation, the sheet's relaxation after the jolt could still take
// Newton to its cap; against its exact surface every step converges, in 29 iterations on
// average over the 4 frames.
TEST(MovingObstacles, ABallAt100MetresPerSecondCarriesASmallSheetAlong) {
  World w = make_world(cotton_sheet(4, 1.0, 1.0),
                       {collider(SphereShape{0.2},
                                 ScriptedMotion{.initial = {.position = Vec3(0.0, 2.0, 0.0)},
                                                .linear_velocity = Vec3(0.0, -100.0, 0.0)},
                                 1)});
  EXPECT_LT(run_audited(w, 4), 4 * 50);
}

// A box keyframed through a 5 x 5 sheet in one frame (its bottom from 0.3 m above the sheet to
// 0.9 m below it, 36 m/s). Where a corner of the box meets the cloth vertex just beyond it, the
// push took only the triangles the corner was over: the box stalled against that vertex for
// all 300 Newton iterations of the step (0.7 s). Pushed toward the triangle's nearest point,
// every step converges.
TEST(MovingObstacles, ABoxKeyframedThroughTheSheetInOneFrameCarriesItAlong) {
  const KeyframedMotion jump{{{0.0, Vec3(0.0, 1.5, 0.0), Quat::Identity()},
                              {kFrame, Vec3(0.0, 0.3, 0.0), Quat::Identity()},
                              {1.0, Vec3(0.0, -5.0, 0.0), Quat::Identity()}}};
  World w = make_world(cotton_sheet(4, 1.0, 1.0),
                       {collider(BoxShape{Vec3(0.2, 0.2, 0.2)}, jump)}, newton(300));
  EXPECT_LT(run_audited(w, 4), 4 * 50);
}

// The automatic barrier stiffness balances the larger of a particle's weight and the force
// that brings it to a moving collider's speed within the substep (contact_term.cpp); a
// collider slower than g h, and a hand-set stiffness, leave it as it is.
TEST(MovingObstacles, AFastColliderRaisesTheAutomaticStiffnessForItsSubstep) {
  const ClothDesc sheet = cotton_sheet(4, 1.0, 1.0);
  const auto ball_at = [](double speed) {
    return collider(SphereShape{0.2},
                    ScriptedMotion{.initial = {.position = Vec3(0.0, 2.0, 0.0)},
                                   .linear_velocity = Vec3(0.0, -speed, 0.0)});
  };
  World still = make_world(sheet, {ball_at(0.0)});
  const double weight_kappa = still.contact->stiffness();
  ASSERT_GT(weight_kappa, 0.0);
  const double h = 0.01, g = 9.81;  // cotton_sheet's gravity
  for (const double speed : {0.05, 10.0, 100.0}) {
    World w = make_world(sheet, {ball_at(speed)});
    w.contact->prepare(w.sim.state(), h);
    EXPECT_NEAR(w.contact->stiffness() / weight_kappa, std::max(1.0, speed / (h * g)), 1e-9)
        << speed << " m/s";
  }
  auto set = ContactTerm::create(std::make_shared<const ClothModel>(still.sim.model()),
                                 {.thickness = 2e-3, .stiffness = 1e5},
                                 {.colliders = {ball_at(100.0)}});
  ASSERT_TRUE(set) << set.error().message;
  (*set)->prepare(still.sim.state(), h);
  EXPECT_EQ((*set)->stiffness(), 1e5);
}

// A box turning about its vertical axis under a sheet draped over it: its side faces and
// corners sweep into the hanging cloth (0.28 m/s at the corners) and must push it round.
TEST(MovingObstacles, ABoxTurningUnderADrapedClothPushesItRound) {
  World w = make_world(cotton_sheet(10, 0.5, 0.103),
                       {collider(BoxShape{Vec3(0.1, 0.1, 0.1)},
                                 ScriptedMotion{.angular_velocity = Vec3(0.0, 2.0, 0.0)})});
  run_audited(w, 30);
  EXPECT_GT(w.contact->stats(w.sim.state().positions).active_pairs, 10);  // it is draped
  // The box's pose is its motion's, exactly where the last substep ended.
  const RigidPose expected = pose_at(w.contact->colliders()[0].model().desc.motion, 30 * kFrame);
  EXPECT_TRUE(w.contact->collider_pose(0).rotation.isApprox(expected.rotation, 1e-12));
  // The sheet turned with the box: a corner particle is no longer where it fell.
  const Vec3 corner = w.sim.state().position(0);
  EXPECT_GT(std::abs(std::atan2(corner.z(), corner.x()) - std::atan2(-0.25, -0.25)), 0.1);
}

// The box's edges sweep across the sheet's edges: the push covers edge-edge pairs too (without
// that, this box stalled short of its pose in frame 10).
TEST(MovingObstacles, AKeyframedBoxLiftsAPinnedClothAndItsCacheReplaysIt) {
  // A box rising 0.2 m in 0.3 s while turning 30 degrees, then resting, under a sheet pinned at
  // its four corners.
  const int cells = 10;
  ClothDesc desc = cotton_sheet(cells, 0.6, 0.0);
  for (int i : {0, cells}) {
    for (int j : {0, cells}) desc.particles[grid_index(cells, i, j)].pinned = true;
  }
  const Quat turned(Eigen::AngleAxisd(std::numbers::pi / 6.0, Vec3::UnitY()));
  KeyframedMotion keys{{{0.0, Vec3(0.0, -0.25, 0.0), Quat::Identity()},
                        {0.3, Vec3(0.0, -0.06, 0.0), turned},
                        {1.0, Vec3(0.0, -0.06, 0.0), turned}}};
  World w = make_world(desc, {collider(BoxShape{Vec3(0.1, 0.1, 0.1)}, keys, 1)});

  // colliders.pc2 as the CLI writes it: the term's collider points, frame by frame.
  const std::filesystem::path path =
      std::filesystem::path(::testing::TempDir()) / "animkit_moving_obstacles_colliders.pc2";
  auto writer = Pc2Writer::open(path, collider_point_count(w.contact->colliders()));
  ASSERT_TRUE(writer);
  ASSERT_TRUE(writer->add_frame(w.contact->collider_points()));
  const int frames = 24;
  for (int frame = 1; frame <= frames; ++frame) {
    run_audited(w, 1, frame);
    ASSERT_TRUE(writer->add_frame(w.contact->collider_points()));
  }
  ASSERT_TRUE(writer->finish());
  double highest = -1.0;
  for (int i = 0; i < w.sim.model().particle_count(); ++i)
    highest = std::max(highest, w.sim.state().position(i).y());
  EXPECT_GT(highest, 0.035);  // lifted by the box's top at 0.04 m

  const auto cache = read_pc2(path);
  ASSERT_TRUE(cache) << cache.error().message;
  ASSERT_EQ(cache->frames.size(), static_cast<std::size_t>(frames + 1));
  for (int frame = 0; frame <= frames; ++frame) {
    const Eigen::VectorXd expected = collider_points(w.contact->colliders(), frame * kFrame);
    ASSERT_EQ(cache->frames[frame].size(), static_cast<std::size_t>(expected.size()));
    for (Eigen::Index k = 0; k < expected.size(); ++k)
      EXPECT_NEAR(cache->frames[frame][k], expected[k], 1e-6) << "frame " << frame;
  }
}

TEST(MovingObstacles, AColliderMovingAwayLeavesTheClothToFall) {
  // The sheet starts resting 1 mm above a box that then drops away at 3 m/s, faster than the
  // sheet can fall after it.
  KeyframedMotion keys{
      {{0.1, Vec3::Zero(), Quat::Identity()}, {0.2, Vec3(0.0, -0.3, 0.0), Quat::Identity()}}};
  World w =
      make_world(cotton_sheet(8, 0.3, 0.101), {collider(BoxShape{Vec3(0.2, 0.1, 0.2)}, keys)});
  const int iterations = run_audited(w, 18);
  EXPECT_LT(iterations, 18 * 30);
  double lowest = 1.0;
  for (int i = 0; i < w.sim.model().particle_count(); ++i)
    lowest = std::min(lowest, w.sim.state().position(i).y());
  EXPECT_LT(lowest, 0.05);  // it fell
}

// Dragged 2 cm per frame, in one substep: with normal pushes only it stalled short of the
// target (like the sphere above; 109 s of Newton iterations in all), and needed four substeps
// (5 mm each, 2.5 contact distances); carrying the pushed cloth, one reaches it every frame.
TEST(MovingObstacles, AColliderDraggedByHandPushesTheClothWithTheSameGuarantee) {
  // A static ball the viewer drags through a hanging sheet, 2 cm per frame.
  SimulationOptions options = newton();
  options.substeps = 1;
  World w =
      make_world(hanging_sheet(8, 0.5, 0.25),
                 {collider(SphereShape{0.1}, ScriptedMotion{.initial =
                                                                {
                                                                    .position = Vec3(0, 0, -0.12),
                                                                }})},
                 options);
  const ClothState start = w.sim.state();
  for (int frame = 1; frame <= 10; ++frame) {
    const RigidPose target{Vec3(0.0, 0.0, -0.12 + 0.02 * frame), Quat::Identity()};
    ASSERT_TRUE(w.contact->move_collider(0, target));
    const auto report = w.sim.step(kFrame);
    ASSERT_TRUE(report) << report.error().message;
    EXPECT_TRUE(report->converged) << "frame " << frame;
    EXPECT_EQ(w.contact->collider_pose(0).position, target.position);
    TriangleMesh ball = w.contact->colliders()[0].model().surface;
    for (Vec3& v : ball.vertices) v = target.to_world(v);
    Eigen::VectorXd points(3 * static_cast<Eigen::Index>(ball.vertices.size()));
    for (std::size_t i = 0; i < ball.vertices.size(); ++i)
      points.segment<3>(3 * static_cast<Eigen::Index>(i)) = ball.vertices[i];
    EXPECT_EQ(w.contact->collider_points(), points);
    EXPECT_FALSE(audit::meshes_intersect(sheet_mesh(w.sim), ball)) << "frame " << frame;
  }
  for (int i = 0; i < w.sim.model().particle_count(); ++i) {
    if (w.sim.model().pinned[i]) {
      EXPECT_EQ(w.sim.state().position(i), start.position(i));
    }
  }
  double furthest = 0.0;
  for (int i = 0; i < w.sim.model().particle_count(); ++i)
    furthest = std::max(furthest, w.sim.state().position(i).z());
  EXPECT_GT(furthest, 0.05);
}

TEST(MovingObstacles, AColliderThatCannotGetThroughLeavesTheStepUnconverged) {
  // Every particle pinned: the ball can only close in on the sheet, never reach its pose. The
  // step is then not converged (the term is not settled), and still nothing intersects.
  ClothDesc desc = hanging_sheet(6, 0.4, 0.2);
  for (ParticleDesc& p : desc.particles) p.pinned = true;
  World w = make_world(
      desc,
      {collider(SphereShape{0.1}, ScriptedMotion{.initial = {.position = Vec3(0.0, 0.0, -0.12)},
                                                 .linear_velocity = Vec3(0.0, 0.0, 3.0)})},
      newton(20));
  for (int frame = 1; frame <= 3; ++frame) {
    const auto report = w.sim.step(kFrame);
    ASSERT_TRUE(report) << report.error().message;
    TriangleMesh ball = w.contact->colliders()[0].model().surface;
    const Eigen::VectorXd points = w.contact->collider_points();
    for (std::size_t i = 0; i < ball.vertices.size(); ++i)
      ball.vertices[i] = points.segment<3>(3 * static_cast<Eigen::Index>(i));
    EXPECT_FALSE(audit::meshes_intersect(sheet_mesh(w.sim), ball)) << "frame " << frame;
    if (frame >= 2) {  // by then it has reached the sheet
      EXPECT_FALSE(report->converged);
      EXPECT_FALSE(w.contact->settled());
    }
  }
}

TEST(MovingObstacles, ObstaclesKeepWhereTheSubstepStarted) {
  // What friction reads: the displacement since the substep's start, here the ball's v h.
  const Vec3 velocity(0.0, -1.0, 0.0);
  World w =
      make_world(cotton_sheet(4, 0.2, 0.5),
                 {collider(SphereShape{0.1}, ScriptedMotion{.linear_velocity = velocity}, 1)});
  ASSERT_TRUE(w.sim.step(kFrame));
  const Eigen::VectorXd moved =
      w.contact->obstacle_positions() - w.contact->obstacle_start_positions();
  for (Eigen::Index v = 0; v < moved.size() / 3; ++v)
    EXPECT_TRUE(moved.segment<3>(3 * v).isApprox(velocity * kFrame, 1e-12)) << v;
}

TEST(MovingObstacles, BadCollidersAndTargetsAreRefusedByName) {
  auto sim = ClothSimulator::create(cotton_sheet(3, 0.3, 1.0), {});
  ASSERT_TRUE(sim);
  const auto model = std::make_shared<const ClothModel>(sim->model());
  auto floor = Collider::create({.name = "floor", .shape = PlaneShape{}});
  ASSERT_TRUE(floor);
  auto refused = ContactTerm::create(model, {}, {.colliders = {*floor}});
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error().message,
            "collider 'floor' is a plane: contact takes a horizontal floor as the ground height");

  auto bad_keys = Collider::create(
      {.name = "box", .shape = BoxShape{}, .motion = KeyframedMotion{{{1.0}, {1.0}}}});
  ASSERT_FALSE(bad_keys);
  EXPECT_EQ(bad_keys.error().message,
            "collider 'box': keyframe 1 is at 1 s, not after keyframe 0 at 1 s");

  auto ball = Collider::create({.name = "ball"});
  ASSERT_TRUE(ball);
  auto term = ContactTerm::create(model, {}, {.colliders = {*ball}});
  ASSERT_TRUE(term);
  auto missing = (*term)->move_collider(1, {});
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().message, "no collider 1: the contact term has 1 collider(s)");
  Quat doubled = Quat::Identity();
  doubled.coeffs() *= 2.0;
  auto scaled = (*term)->move_collider(0, {Vec3::Zero(), doubled});
  ASSERT_FALSE(scaled);
  EXPECT_EQ(scaled.error().message,
            "collider 'ball': target pose: rotation is not a unit quaternion (norm 2)");
  auto nowhere = (*term)->move_collider(0, {Vec3(0.0, std::nan(""), 0.0), Quat::Identity()});
  ASSERT_FALSE(nowhere);
  EXPECT_TRUE(nowhere.error().message.starts_with(
      "collider 'ball': target pose: position has a non-finite coordinate"));
}

TEST(MovingObstacles, OnlyAMotionThatChangesThePoseMoves) {
  EXPECT_FALSE(moves(ScriptedMotion{.initial = {.position = Vec3(1.0, 2.0, 3.0)}}));
  EXPECT_TRUE(moves(ScriptedMotion{.angular_velocity = Vec3(0.0, 1e-3, 0.0)}));
  Quat flipped = Quat::Identity();
  flipped.coeffs() = -flipped.coeffs();  // the same rotation
  EXPECT_FALSE(moves(KeyframedMotion{{{0.0}, {1.0, Vec3::Zero(), flipped}}}));
  EXPECT_TRUE(moves(KeyframedMotion{{{0.0}, {1.0, Vec3(0.0, 0.0, 0.1)}}}));
}

}  // namespace
}  // namespace animkit
