#include "animkit/scene/cloth_scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "animkit/cloth/integrator_registry.h"
#include "animkit/scene/cloth_scenes.h"

namespace animkit {
namespace {

ClothScene lab_cloth() {
  auto scene = ClothScene::create();
  EXPECT_TRUE(scene.has_value()) << scene.error().message;
  return std::move(*scene);
}

int free_corner(const ClothScene& scene) {
  return grid_index(scene.options().grid.cells, scene.options().grid.cells,
                    scene.options().grid.cells);
}

TEST(ClothScene, TheMouseSpringPullsTheGrabbedParticleToTheCursor) {
  ClothScene held = lab_cloth(), free = lab_cloth();
  const int p = free_corner(held);
  const Vec3 target = held.simulator().state().position(p) + Vec3(0.0, 0.8, 0.0);
  ASSERT_TRUE(held.set_drag({p, target}).has_value());
  for (int i = 0; i < 90; ++i) {
    ASSERT_TRUE(held.step().has_value());
    ASSERT_TRUE(free.step().has_value());
  }
  const double held_gap = (held.simulator().state().position(p) - target).norm();
  const double free_gap = (free.simulator().state().position(p) - target).norm();
  EXPECT_LT(held_gap, 0.5 * free_gap);
  DrawList list;
  held.describe(list);
  EXPECT_EQ(list.points.back().position, target.cast<float>());  // the cursor is drawn
  held.clear_drag();
  EXPECT_FALSE(held.drag().has_value());
}

TEST(ClothScene, PinningHoldsAParticleAndUnpinningReleasesIt) {
  ClothScene scene = lab_cloth();
  const int corner = free_corner(scene);
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(scene.step().has_value());
  ASSERT_TRUE(scene.toggle_pin(corner).has_value());
  const Vec3 pinned_at = scene.simulator().state().position(corner);
  for (int i = 0; i < 30; ++i) ASSERT_TRUE(scene.step().has_value());
  EXPECT_EQ(scene.simulator().state().position(corner), pinned_at);

  const int lab_pin = grid_index(scene.options().grid.cells, 0, 0);
  ASSERT_TRUE(scene.simulator().model().pinned[lab_pin]);
  const double y = scene.simulator().state().position(lab_pin).y();
  ASSERT_TRUE(scene.toggle_pin(lab_pin).has_value());
  for (int i = 0; i < 30; ++i) ASSERT_TRUE(scene.step().has_value());
  EXPECT_LT(scene.simulator().state().position(lab_pin).y(), y - 0.01);

  const auto bad = scene.toggle_pin(121);
  ASSERT_FALSE(bad.has_value());
  EXPECT_EQ(bad.error().message, "particle 121 is out of range (the cloth has 121)");
}

TEST(ClothScene, ApplyKeepsTheMotionAndResetStartsOver) {
  ClothScene scene = lab_cloth();
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(scene.step().has_value());
  const ClothState moving = scene.simulator().state();
  ClothSceneOptions stiffer = scene.options();
  stiffer.grid.stiffness = 250.0;
  ASSERT_TRUE(scene.apply(stiffer).has_value());
  EXPECT_EQ(scene.simulator().state().positions, moving.positions);
  EXPECT_EQ(scene.simulator().model().stiffness.front(), 250.0);

  ClothSceneOptions bigger = scene.options();
  bigger.grid.cells = 14;
  ASSERT_TRUE(scene.apply(bigger).has_value());
  EXPECT_EQ(scene.simulator().model().particle_count(), 15 * 15);

  ClothSceneOptions broken = scene.options();
  broken.time_step = 0.0;
  const auto rejected = scene.apply(broken);
  ASSERT_FALSE(rejected.has_value());
  EXPECT_EQ(rejected.error().message, "time step must be between 1e-06 and 10, got 0");
  EXPECT_EQ(scene.options().grid.cells, 14);  // unchanged
}

TEST(ClothScene, PickFindsTheParticleUnderTheCursorNearestTheEye) {
  ClothScene scene = lab_cloth();
  // Straight down from above the sheet: every particle projects apart.
  OrbitCamera camera;
  camera.focus = Vec3(1.0, 1.5, 0.0);
  camera.pitch = 1.5;
  camera.distance = 4.0;
  const auto at = camera.project(scene.simulator().state().position(37), 800.0, 600.0);
  ASSERT_TRUE(at.has_value());
  EXPECT_EQ(scene.pick(camera, at->x() + 3.0, at->y(), 800.0, 600.0, 6.0), 37);
  EXPECT_FALSE(scene.pick(camera, at->x() + 30.0, at->y() + 30.0, 800.0, 600.0, 2.0).has_value());
  // Edge-on along a grid row, particles line up one behind another: the nearest one wins.
  OrbitCamera side;
  side.focus = Vec3(1.0, 1.5, 0.0);
  side.yaw = 1.5707963267948966;  // looking from +x towards -x, along the row of particles
  side.pitch = 0.0;
  side.distance = 5.0;
  const int near_end = grid_index(10, 10, 5), far_end = grid_index(10, 0, 5);
  const auto p = side.project(scene.simulator().state().position(near_end), 800.0, 600.0);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(scene.pick(side, p->x(), p->y(), 800.0, 600.0, 4.0), near_end);
  EXPECT_NE(scene.pick(side, p->x(), p->y(), 800.0, 600.0, 4.0), far_end);
}

TEST(ClothScene, ReleasingTheDragRemovesItsForce) {
  ClothScene dragged = lab_cloth();
  const int p = free_corner(dragged);
  ASSERT_TRUE(dragged.set_drag({p, Vec3(3.0, 3.0, 0.0)}).has_value());
  ASSERT_TRUE(dragged.step().has_value());
  dragged.clear_drag();
  // From the same state, the released cloth steps exactly as a cloth never dragged.
  const ClothState after_drag = dragged.simulator().state();
  ASSERT_TRUE(dragged.step().has_value());
  ClothSimulator reference = *ClothSimulator::create(make_grid_cloth(), {});
  ASSERT_TRUE(reference.set_state(after_drag).has_value());
  ASSERT_TRUE(reference.step(dragged.options().time_step).has_value());
  EXPECT_LT((reference.state().positions - dragged.simulator().state().positions).norm(), 1e-12);
}

TEST(ClothScene, TheMouseSpringStaysStableAtTheLargestTimeStep) {
  ClothSceneOptions options;
  options.time_step = 0.1;  // the viewer's slider maximum
  for (const IntegratorEntry& entry : cloth_integrators()) {
    options.simulation.integrator = entry.defaults;
    auto scene = ClothScene::create(options);
    ASSERT_TRUE(scene.has_value());
    const int p = free_corner(*scene);
    const Vec3 target(2.5, 2.5, 1.0);
    ASSERT_TRUE(scene->set_drag({p, target}).has_value());
    for (int i = 0; i < 100; ++i) ASSERT_TRUE(scene->step().has_value()) << "step " << i;
    EXPECT_LT((scene->simulator().state().position(p) - target).norm(), 1.5);
  }
}

TEST(ClothScene, RecordsTheEnergyOfEveryStep) {
  ClothScene scene = lab_cloth();
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(scene.step().has_value());
  ASSERT_EQ(scene.energy_history().size(), 5u);
  EXPECT_EQ(scene.energy_history().back(), scene.last_step()->energy);
}

// A small cotton sheet (8 x 8 cells, 0.6 m) 0.45 m up, over a 0.2 m ball resting on the
// ground: it lands on the ball within a few steps at 1/30 s.
ClothWorldDesc small_drape() {
  ClothWorldDesc world = cotton_sheet_world(8, 0.6, 0.45);
  ColliderDesc ball{.name = "ball",
                    .shape = SphereShape{0.2},
                    .motion = ScriptedMotion{.initial = {.position = Vec3(0.0, 0.2, 0.0)}},
                    .tessellation = 2};
  world.colliders.push_back(ball);
  world.ground = GroundDesc{};
  return world;
}

ClothScene drape_scene() {
  auto scene = ClothScene::create(small_drape(), "small drape");
  EXPECT_TRUE(scene.has_value()) << scene.error().message;
  return std::move(*scene);
}

TEST(ClothScene, OpensEveryBuiltInSceneWithItsCollidersAndGround) {
  for (const ClothSceneEntry& entry : cloth_scenes()) {
    const ClothWorldDesc world = entry.make();
    auto scene = ClothScene::create(world, std::string(entry.name));
    ASSERT_TRUE(scene.has_value()) << entry.name << ": " << scene.error().message;
    EXPECT_EQ(scene->name(), entry.name);
    EXPECT_EQ(scene->colliders().size(), world.colliders.size());
    EXPECT_EQ(scene->contact() != nullptr, world.has_contact()) << entry.name;
    EXPECT_EQ(scene->lab_parameters(), entry.name == "lab") << entry.name;
    DrawList list;
    scene->describe(list);
    const std::size_t cloth_triangles = scene->simulator().model().triangles.size();
    std::size_t collider_triangles = 0;
    for (const Collider& c : scene->colliders())
      collider_triangles += c.model().surface.triangles.size();
    EXPECT_EQ(list.triangles.size(), 3 * (cloth_triangles + collider_triangles)) << entry.name;
    if (world.ground) {  // the floor grid is the ground, at its height
      ASSERT_FALSE(list.lines.empty());
      EXPECT_EQ(list.lines.front().a.y(), static_cast<float>(world.ground->height));
    }
    const Eigen::AlignedBox3d focus = scene->focus_bounds();
    for (const Collider& c : scene->colliders()) {
      for (const Vec3& v : c.world_vertices()) EXPECT_TRUE(focus.contains(v)) << entry.name;
    }
  }
}

TEST(ClothScene, LoadSwitchesScenesAndABadSceneLeavesTheOldOne) {
  ClothScene scene = lab_cloth();
  ASSERT_TRUE(scene.step().has_value());
  ASSERT_TRUE(scene.load(small_drape(), "small drape").has_value());
  EXPECT_EQ(scene.name(), "small drape");
  EXPECT_EQ(scene.simulator().model().particle_count(), 81);
  EXPECT_FALSE(scene.last_step().has_value());  // from its start
  EXPECT_TRUE(scene.energy_history().empty());
  EXPECT_FALSE(scene.lab_parameters());

  ClothWorldDesc inside = small_drape();
  std::get<GridClothOptions>(inside.cloth).height = 0.2;  // through the ball's middle
  const auto refused = scene.load(inside, "inside");
  ASSERT_FALSE(refused.has_value());
  EXPECT_NE(refused.error().message.find("starts inside collider 'ball'"), std::string::npos)
      << refused.error().message;
  EXPECT_EQ(scene.name(), "small drape");
  EXPECT_EQ(scene.simulator().model().particle_count(), 81);
  ASSERT_TRUE(scene.step().has_value());
}

TEST(ClothScene, ACottonSheetLandsOnTheBallAndShowsItsContacts) {
  ClothScene scene = drape_scene();
  const double ball_top = 0.4;
  int touching = 0;
  for (int i = 0; i < 15; ++i) {
    const auto report = scene.step();
    ASSERT_TRUE(report.has_value()) << report.error().message;
    ASSERT_TRUE(report->has_contact);
    EXPECT_TRUE(report->converged) << "step " << i;
    if (report->contact_pairs > 0) ++touching;
    for (int p = 0; p < scene.simulator().model().particle_count(); ++p)
      ASSERT_GT(scene.simulator().state().position(p).norm(), 0.0);  // no NaN
  }
  EXPECT_GT(touching, 5);
  std::vector<ContactPoint> points;
  scene.contact_points(points);
  ASSERT_EQ(static_cast<int>(points.size()), scene.last_step()->contact_pairs);
  double closest = 1.0;
  for (const ContactPoint& p : points) {
    EXPECT_LT(p.distance, scene.world().contact.thickness);
    if (p.with == ContactPoint::With::collider) {
      // On top of the ball: the cloth just above its surface.
      EXPECT_GT(p.cloth.y(), 0.2);
      EXPECT_LT((p.other - Vec3(0.0, 0.2, 0.0)).norm(), 0.2 + 1e-9);
      EXPECT_LT(p.cloth.y(), ball_top + 0.01);
    }
    closest = std::min(closest, p.distance);
  }
  EXPECT_DOUBLE_EQ(closest, scene.last_step()->min_contact_distance);
  // Drawn when asked: a red point on the cloth's side of every contact.
  DrawList plain, with_contacts;
  scene.describe(plain);
  scene.describe(with_contacts, {.contacts = true});
  EXPECT_EQ(with_contacts.points.size(), plain.points.size() + 2 * points.size());
  EXPECT_EQ(with_contacts.lines.size(), plain.lines.size() + points.size());
}

TEST(ClothScene, ThePressGrabsTheBallOrTheClothWhicheverIsInFront) {
  ClothScene scene = drape_scene();
  // From the side, level with the ball's centre: the sheet (0.45 m up) is above the view's
  // centre, the ball in it.
  OrbitCamera camera;
  camera.focus = Vec3(0.0, 0.2, 0.0);
  camera.yaw = 0.0;
  camera.pitch = 0.0;
  camera.distance = 2.0;
  const ClothPick ball = scene.pick_handle(camera, 400.0, 300.0, 800.0, 600.0, 8.0);
  ASSERT_TRUE(ball.collider.has_value());
  EXPECT_FALSE(ball.particle.has_value());
  EXPECT_EQ(ball.collider->collider, 0);
  EXPECT_NEAR(ball.collider->point.z(), 0.2, 0.01);  // its near side
  // The sheet's middle particle on its edge nearest the camera.
  int near_edge = 0;
  const ClothState& state = scene.simulator().state();
  for (int p = 0; p < scene.simulator().model().particle_count(); ++p) {
    const Vec3 x = state.position(p), best = state.position(near_edge);
    if (x.z() > best.z() + 1e-9 ||
        (x.z() > best.z() - 1e-9 && std::abs(x.x()) < std::abs(best.x())))
      near_edge = p;
  }
  const Vec3 particle = state.position(near_edge);
  ASSERT_NEAR(particle.z(), 0.3, 1e-9);
  ASSERT_NEAR(particle.x(), 0.0, 1e-9);
  const auto at = camera.project(particle, 800.0, 600.0);
  ASSERT_TRUE(at.has_value());
  const ClothPick cloth = scene.pick_handle(camera, at->x(), at->y(), 800.0, 600.0, 8.0);
  EXPECT_EQ(cloth.particle, near_edge);
  EXPECT_FALSE(cloth.collider.has_value());
  EXPECT_FALSE(scene.pick_handle(camera, 5.0, 5.0, 800.0, 600.0, 8.0).collider.has_value());
}

TEST(ClothScene, DraggingABallAsksForThePoseThatKeepsTheGrabUnderTheCursor) {
  ClothScene scene = drape_scene();
  const auto grab = pick_collider(scene.colliders(), {Vec3(0.0, 0.2, 3.0), Vec3(0, 0, -1)});
  ASSERT_TRUE(grab.has_value());
  scene.grab_collider(*grab);
  // Down and aside, away from the sheet above it: nothing is in its way.
  const Vec3 cursor = grab->point + Vec3(0.1, -0.15, 0.0);
  const auto moved = scene.drag_collider_to(cursor);
  ASSERT_TRUE(scene.collider_drag().has_value());
  const RigidPose& target = scene.collider_drag()->target;
  EXPECT_LT((target.position - Vec3(0.1, 0.05, 0.0)).norm(), 1e-12);
  // The solver takes the pose as the ball's target: it stays put until the next step moves it
  // there (as far as the cloth in its way lets it), and is drawn where the solver put it.
  ASSERT_TRUE(moved.has_value()) << moved.error().message;
  EXPECT_EQ(scene.colliders()[0].pose().position, Vec3(0.0, 0.2, 0.0));
  ASSERT_TRUE(scene.step());
  EXPECT_LT((scene.colliders()[0].pose().position - target.position).norm(), 1e-12);
  DrawList list;
  scene.describe(list);
  EXPECT_EQ(list.points.back().position, cursor.cast<float>());
  scene.release_collider();
  EXPECT_FALSE(scene.collider_drag().has_value());

  EXPECT_EQ(scene.move_collider(1, {}).error().message,
            "collider 1 is out of range (the scene has 1)");
  RigidPose bad;
  bad.position.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(scene.move_collider(0, bad).has_value());
  EXPECT_FALSE(ClothScene(lab_cloth()).move_collider(0, {}).has_value());
}

TEST(ClothScene, LiveChangesToAContactSceneKeepItsMotionAndPins) {
  ClothScene scene = drape_scene();
  for (int i = 0; i < 6; ++i) ASSERT_TRUE(scene.step().has_value());
  ASSERT_TRUE(scene.toggle_pin(0).has_value());
  const ClothState moving = scene.simulator().state();
  ClothWorldDesc world = scene.world();
  world.time_step = 1.0 / 60.0;
  world.contact.thickness = 3e-3;
  set_tolerance(world.simulation.integrator, 1e-5);
  ASSERT_TRUE(scene.apply_world(world).has_value());
  EXPECT_EQ(scene.simulator().state().positions, moving.positions);
  EXPECT_EQ(scene.simulator().state().velocities.tail(3 * 80), moving.velocities.tail(3 * 80));
  EXPECT_TRUE(scene.simulator().model().pinned[0]);
  EXPECT_EQ(scene.options().time_step, 1.0 / 60.0);
  EXPECT_EQ(scene.world().contact.thickness, 3e-3);
  const Vec3 pinned = scene.simulator().state().position(0);
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(scene.step().has_value());
  EXPECT_EQ(scene.simulator().state().position(0), pinned);

  // Another sheet starts the scene over; restart too.
  std::get<GridClothOptions>(world.cloth).cells = 6;
  ASSERT_TRUE(scene.apply_world(world).has_value());
  EXPECT_EQ(scene.simulator().model().particle_count(), 49);
  EXPECT_FALSE(scene.last_step().has_value());
  ASSERT_TRUE(scene.step().has_value());
  ASSERT_TRUE(scene.restart().has_value());
  EXPECT_FALSE(scene.last_step().has_value());
  EXPECT_EQ(scene.world().contact.thickness, 3e-3);  // the changed settings kept
}

}  // namespace
}  // namespace animkit
