// Building a world from its description: the lab's unchanged, contact and air wired in, and
// clear errors for worlds that cannot start.
#include "animkit/cloth/cloth_world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>

#include "animkit/cloth/material.h"
#include "animkit/io/cloth_scene_file.h"

namespace animkit {
namespace {

TEST(ClothWorld, TheDefaultIsTheLabsClothBitForBit) {
  auto world = build_cloth_world({});
  ASSERT_TRUE(world) << world.error().message;
  auto lab = ClothSimulator::create(make_grid_cloth(), {});
  ASSERT_TRUE(lab);
  EXPECT_FALSE(world->contact);
  EXPECT_FALSE(world->air);
  for (int k = 0; k < 20; ++k) {
    ASSERT_TRUE(world->simulator.step(1.0 / 60.0));
    ASSERT_TRUE(lab->step(1.0 / 60.0));
  }
  EXPECT_EQ(world->simulator.state().positions, lab->state().positions);
}

ClothWorldDesc sheet_over_ball() {
  ClothWorldDesc desc;
  GridClothOptions grid;
  grid.cells = 8;
  grid.size = 1.0;
  grid.height = 0.5;
  grid.pins = GridPins::none;
  grid.offset = Vec3(-0.5, 0.0, 0.0);
  desc.cloth = grid;
  ColliderDesc ball;
  ball.name = "ball";
  ball.shape = SphereShape{0.2};
  ball.motion = ScriptedMotion{.initial = {.position = Vec3(0, 0.2, 0)}};
  desc.colliders.push_back(ball);
  desc.ground = GroundDesc{};
  return desc;
}

TEST(ClothWorld, ContactIsWiredAndReportsEachStep) {
  auto world = build_cloth_world(sheet_over_ball());
  ASSERT_TRUE(world) << world.error().message;
  ASSERT_TRUE(world->contact);
  ASSERT_TRUE(world->friction);  // the default coefficients are not zero
  ASSERT_EQ(world->colliders.size(), 1u);
  // Newton gets room for impacts.
  EXPECT_GE(std::get<NewtonSettings>(world->simulator.options().integrator).max_iterations,
            kContactNewtonIterations);
  auto step = world->simulator.step(1.0 / 60.0);
  ASSERT_TRUE(step) << step.error().message;
  EXPECT_TRUE(step->has_contact);
  EXPECT_GT(step->min_contact_distance, 0.0);
}

// One step of `fast`, and of `reference` from the same state, both converged: their reports and
// how far apart (largest coordinate, m) the two steps end. Nothing when a step failed.
struct StepsFromOneState {
  StepReport fast, reference;
  double apart = 0.0;
};
std::optional<StepsFromOneState> step_beside(ClothWorld& fast, ClothWorld& reference, int frame) {
  EXPECT_TRUE(reference.simulator.set_state(fast.simulator.state()));
  const auto exact = reference.simulator.step(1.0 / 60.0);
  const auto step = fast.simulator.step(1.0 / 60.0);
  EXPECT_TRUE(exact && step);
  if (!exact || !step) return std::nullopt;
  EXPECT_TRUE(exact->converged && step->converged) << "frame " << frame;
  const double apart = (fast.simulator.state().positions - reference.simulator.state().positions)
                           .lpNorm<Eigen::Infinity>();
  return StepsFromOneState{*step, *exact, apart};
}

// The reference quality mode (IPC's settings) and the fast settings: what each sets,
// and that on a sheet landing on a ball they end each step within a millimetre of each other.
TEST(ClothWorld, FastContactSettingsFollowTheReference) {
  ClothWorldDesc reference_desc = sheet_over_ball();
  use_reference_contact_settings(reference_desc);
  ClothWorldDesc fast_desc = sheet_over_ball();
  use_fast_settings(fast_desc);
  const auto& reference_newton = std::get<NewtonSettings>(reference_desc.simulation.integrator);
  const auto& fast_newton = std::get<NewtonSettings>(fast_desc.simulation.integrator);
  EXPECT_EQ(reference_desc.contact.hessian, BarrierHessian::projected);
  EXPECT_EQ(reference_newton.velocity_tolerance, 0.0);
  EXPECT_EQ(reference_newton.linear_forcing, 0.0);
  EXPECT_EQ(fast_desc.contact.hessian, BarrierHessian::adaptive);
  EXPECT_EQ(fast_newton.velocity_tolerance, 1e-3);
  EXPECT_EQ(fast_newton.linear_forcing, 0.1);
  EXPECT_EQ(reference_newton.projection, HessianProjection::when_indefinite);
  EXPECT_EQ(fast_newton.projection, HessianProjection::with_terms);
  for (const NewtonSettings* newton : {&reference_newton, &fast_newton}) {
    EXPECT_EQ(newton->linear_solver, LinearSolverKind::multigrid);
    EXPECT_EQ(newton->tolerance, 1e-4);
  }
  auto reference = build_cloth_world(reference_desc);
  auto fast = build_cloth_world(fast_desc);
  ASSERT_TRUE(reference && fast);
  for (int frame = 0; frame < 20; ++frame) {
    const auto steps = step_beside(*fast, *reference, frame);
    ASSERT_TRUE(steps);
    EXPECT_LE(steps->apart, 1e-3) << "frame " << frame;
  }
}

// with_terms projects at once while an energy term (contact here) joins the step, and tries the
// exact Hessian first without one: the iterates of `always` and of `when_indefinite`.
TEST(ClothWorld, ProjectingWithTermsFollowsWhetherTermsJoinTheStep) {
  const auto positions_after = [](ClothWorldDesc desc, HessianProjection projection) {
    std::get<NewtonSettings>(desc.simulation.integrator).projection = projection;
    auto world = build_cloth_world(desc);
    EXPECT_TRUE(world) << world.error().message;
    for (int frame = 0; frame < 15 && world; ++frame)
      EXPECT_TRUE(world->simulator.step(1.0 / 30.0));
    return world ? world->simulator.state().positions : Eigen::VectorXd();
  };
  using enum HessianProjection;
  ClothWorldDesc contact = sheet_over_ball();  // in cotton: it lands and folds on the ball
  auto& grid = std::get<GridClothOptions>(contact.cloth);
  grid.material = find_material("cotton")->material;
  grid.gravity = 9.81;
  use_fast_settings(contact);
  EXPECT_EQ(positions_after(contact, with_terms), positions_after(contact, always));
  EXPECT_NE(positions_after(contact, with_terms), positions_after(contact, when_indefinite));
  ClothWorldDesc hanging = contact;  // the same sheet from its two corners, touching nothing
  hanging.colliders.clear();
  hanging.ground.reset();
  std::get<GridClothOptions>(hanging.cloth).pins = GridPins::corners;
  EXPECT_EQ(positions_after(hanging, with_terms), positions_after(hanging, when_indefinite));
  EXPECT_NE(positions_after(hanging, with_terms), positions_after(hanging, always));
}

// A physical sheet with nothing to touch takes the fast settings by default (fast_by_default);
// the lab's cloth keeps the lab's solver. Cotton falling from flat between two pins, each step
// from the same state as Newton solved tightly (a direct solve to 1e-10): within 0.1 mm of it
// but where the sheet buckles as it folds (there the two end in different minima: 1.35 mm
// apart on one step, with either stopping test alone), and always within 5 mm.
TEST(ClothWorld, APhysicalSheetTakesTheFastSettingsAndFollowsATightReference) {
  EXPECT_FALSE(ClothWorldDesc{}.fast_by_default());
  ClothWorldDesc desc;
  GridClothOptions grid{.cells = 20, .size = 1.0, .gravity = 9.81};
  grid.material = find_material("cotton")->material;
  desc.cloth = grid;
  ASSERT_TRUE(desc.is_physical() && desc.fast_by_default());
  use_fast_settings(desc);
  auto fast = build_cloth_world(desc);
  ASSERT_TRUE(fast) << fast.error().message;
  NewtonSettings tight;
  tight.linear_solver = LinearSolverKind::direct;
  tight.tolerance = 1e-10;
  desc.simulation.integrator = tight;
  auto reference = build_cloth_world(desc);
  ASSERT_TRUE(reference) << reference.error().message;
  double farthest = 0.0;
  int fast_iterations = 0, tight_iterations = 0, beyond = 0;
  for (int frame = 0; frame < 40; ++frame) {
    const auto steps = step_beside(*fast, *reference, frame);
    ASSERT_TRUE(steps);
    fast_iterations += steps->fast.newton_iterations;
    tight_iterations += steps->reference.newton_iterations;
    farthest = std::max(farthest, steps->apart);
    beyond += steps->apart > 1e-4 ? 1 : 0;
  }
  EXPECT_LE(beyond, 3);
  EXPECT_LE(farthest, 5e-3);
  EXPECT_LT(fast_iterations, tight_iterations);
}

// A ball falling at `speed` (m/s) from `height` into a 25-particle cotton sheet at 1 m, as a
// scene file makes it (the fast settings, the sphere tessellated at level 3), for 4
// frames of 1/30 s, each of which must converge. Returns the most Newton iterations of a step.
int ball_into_a_small_sheet(double speed, double height) {
  const auto desc = parse_cloth_scene(
      R"({"cloth": {"grid": 4, "size": 1, "height": 1, "material": "cotton", "pins": "none",
                    "offset": [-0.5, 0, 0]},
          "colliders": [{"name": "ball", "radius": 0.2, "position": [0, )" +
          std::to_string(height) + R"(, 0], "velocity": [0, )" + std::to_string(-speed) +
          R"(, 0]}], "frames": 4, "dt": 0.0333333})",
      "ball.json", std::filesystem::current_path());
  EXPECT_TRUE(desc) << desc.error().message;
  if (!desc) return 0;
  auto world = build_cloth_world(*desc);
  EXPECT_TRUE(world) << world.error().message;
  if (!world) return 0;
  int most = 0;
  for (int frame = 1; frame <= desc->frames; ++frame) {
    const auto report = world->simulator.step(desc->time_step);
    EXPECT_TRUE(report) << report.error().message;
    if (!report) return most;
    EXPECT_TRUE(report->converged) << "frame " << frame;
    most = std::max(most, report->newton_iterations);
  }
  return most;
}

// A ball at 10 m/s (33 cm a step). Under Gauss-Newton's barrier Hessian the gaps between the
// ball's vertices and the sheet's triangles fell tenfold per Newton iteration, to 1e-13 m,
// where Additive CCD walks a million steps per pair: the step it meets the sheet took 75
// Newton iterations and 9 s. Pairs whose gap has collapsed now take the exact Hessian
// (kCollapsedGapFraction): 32 iterations, 0.2 s.
TEST(ClothWorld, ABallAt10MetresPerSecondMeetsASmallSheetInFewNewtonIterations) {
  const int most = ball_into_a_small_sheet(10.0, 2.0);
  EXPECT_GT(most, 0);  // the ball met the sheet
  EXPECT_LE(most, 60);
}

// The same sheet met at 100 m/s (3.3 m a step). With the stiffness made for the sheet's
// weight, the barrier let cloth come within 1e-10 m of the ball under the force that carries
// the sheet along, CCD's walks there took up to 260,000 steps, and the second step stopped at
// the 300-iteration cap (4 frames: 4.1 s). With the stiffness made for that force, every step
// converges, the longest in 68 iterations (0.7 s).
TEST(ClothWorld, ABallAt100MetresPerSecondMeetsASmallSheetAndEveryStepConverges) {
  const int most = ball_into_a_small_sheet(100.0, 4.0);
  EXPECT_GT(most, 0);
  EXPECT_LE(most, 150);
}

TEST(ClothWorld, NoFrictionTermWhenEveryCoefficientIsZero) {
  ClothWorldDesc desc = sheet_over_ball();
  desc.colliders[0].friction = 0.0;
  desc.ground->friction = 0.0;
  desc.self_friction = 0.0;
  auto world = build_cloth_world(desc);
  ASSERT_TRUE(world) << world.error().message;
  EXPECT_FALSE(world->friction);
  desc.friction_passes = 0;
  EXPECT_EQ(build_cloth_world(desc).error().message, "friction passes must be at least 1, got 0");
}

TEST(ClothWorld, PlacesAndPinsTheGrid) {
  GridClothOptions grid;
  grid.cells = 4;
  grid.pins = GridPins::edge;
  grid.rotation = Quat(Eigen::AngleAxisd(0.5 * M_PI, Vec3::UnitX()));
  grid.offset = Vec3(1, 2, 3);
  const ClothDesc desc = make_grid_cloth(grid);
  int pinned = 0;
  for (const ParticleDesc& p : desc.particles) pinned += p.pinned ? 1 : 0;
  EXPECT_EQ(pinned, 5);
  // Particle (i, j) = (0, 0) was at (0, 1.5, -1): turned about the centre (1, 1.5, 0), moved.
  EXPECT_NEAR((desc.particles[0].position - Vec3(0 + 1, 1.5 + 1 + 2, 0 + 3)).norm(), 0.0, 1e-12);
  grid.pins = GridPins::none;
  for (const ParticleDesc& p : make_grid_cloth(grid).particles) EXPECT_FALSE(p.pinned);
}

TEST(ClothWorld, RefusesAClothStartingInsideACollider) {
  ClothWorldDesc desc = sheet_over_ball();
  std::get<ScriptedMotion>(desc.colliders[0].motion).initial.position = Vec3(0, 0.5, 0);
  const auto world = build_cloth_world(desc);
  ASSERT_FALSE(world);
  EXPECT_EQ(world.error().message, "particle 30 starts inside collider 'ball'");
}

// The pea of a hostile tester's scene: a 4 x 4 sheet at height 1 and a 3 cm ball whose centre
// sits 0.1 mm above the sheet, in the middle of a triangle, far from its corners and edges.
ClothWorldDesc pea_through_sheet() {
  ClothWorldDesc desc;
  GridClothOptions grid;
  grid.cells = 4;
  grid.size = 1.0;
  grid.height = 1.0;
  grid.material = find_material("cotton")->material;
  desc.cloth = grid;
  ColliderDesc pea;
  pea.name = "pea";
  pea.shape = SphereShape{0.03};
  pea.motion = ScriptedMotion{.initial = {.position = Vec3(0.1, 1.0001, 0.17)}};
  desc.colliders.push_back(pea);
  return desc;
}

TEST(ClothWorld, RefusesAClothStartingThroughACollider) {
  const auto world = build_cloth_world(pea_through_sheet());
  ASSERT_FALSE(world);
  const std::string& message = world.error().message;
  EXPECT_EQ(message.rfind("collider 'pea' passes through the cloth's triangle of particles ", 0),
            0u)
      << message;
  EXPECT_NE(message.find(" at the start"), std::string::npos) << message;
  // Moved clear of the sheet, the same ball starts.
  ClothWorldDesc clear = pea_through_sheet();
  std::get<ScriptedMotion>(clear.colliders[0].motion).initial.position = Vec3(0.1, 1.1, 0.17);
  EXPECT_TRUE(build_cloth_world(clear));
}

// Two 1 m squares of 2 x 2 cells as one mesh: one lying at height 1, one standing through its
// middle (in the plane x = 0.4) from y = 0.7 to 1.5: no vertex of one lies on the other.
MeshClothOptions crossing_squares() {
  MeshClothOptions options;
  TriangleMesh& mesh = options.mesh;
  const auto add_square = [&mesh](const auto& point) {
    const int first = static_cast<int>(mesh.vertices.size());
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 2; ++i) mesh.vertices.push_back(point(0.5 * i, 0.5 * j));
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 2; ++i) {
        const int v = first + 3 * j + i;
        mesh.triangles.push_back({v, v + 1, v + 4});
        mesh.triangles.push_back({v, v + 4, v + 3});
      }
    }
  };
  add_square([](double u, double v) { return Vec3(u, 1.0, v + 0.03); });
  add_square([](double u, double v) { return Vec3(0.4, 0.7 + 0.8 * u, v + 0.07); });
  options.material = find_material("cotton")->material;
  options.gravity = 9.81;
  return options;
}

TEST(ClothWorld, RefusesAClothStartingThroughItself) {
  ClothWorldDesc desc;
  desc.cloth = crossing_squares();
  desc.ground = GroundDesc{};  // contact, for the cloth's self-contact
  const auto world = build_cloth_world(desc);
  ASSERT_FALSE(world);
  EXPECT_EQ(world.error().message.rfind("the cloth passes through itself at the start: its edge "
                                        "between particles ",
                                        0),
            0u)
      << world.error().message;
  // Without self-contact a cloth may cross itself: nothing keeps its layers apart anyway.
  desc.contact.self_contact = false;
  EXPECT_TRUE(build_cloth_world(desc)) << build_cloth_world(desc).error().message;
}

TEST(ClothWorld, RefusesAClothStartingOnASurface) {
  // The sheet lying on a box's top face: every particle over the face is at distance zero.
  ClothWorldDesc desc = sheet_over_ball();
  desc.colliders[0].shape = BoxShape{Vec3(2.0, 0.25, 2.0)};  // its top face at y = 0.5 exactly
  std::get<ScriptedMotion>(desc.colliders[0].motion).initial.position = Vec3(0, 0.25, 0);
  auto world = build_cloth_world(desc);
  ASSERT_FALSE(world);
  const std::string& message = world.error().message;
  EXPECT_NE(message.find(" touches collider 'ball' at the start ("), std::string::npos) << message;
  EXPECT_NE(message.find(" m apart; contact needs them at least 2e-09 m apart)"), std::string::npos)
      << message;
  // Two coincident sheets (self-contact): each vertex lies on the other sheet's triangles.
  MeshClothOptions twice = crossing_squares();
  TriangleMesh& mesh = twice.mesh;
  mesh.triangles.resize(8);
  mesh.vertices.resize(9);
  mesh.vertices.reserve(18);  // the copies below read from the vector they grow
  for (int k = 0; k < 9; ++k) mesh.vertices.push_back(mesh.vertices[k]);
  for (int t = 0; t < 8; ++t)
    mesh.triangles.push_back(
        {mesh.triangles[t][0] + 9, mesh.triangles[t][1] + 9, mesh.triangles[t][2] + 9});
  ClothWorldDesc coincident;
  coincident.cloth = twice;
  coincident.ground = GroundDesc{};
  world = build_cloth_world(coincident);
  ASSERT_FALSE(world);
  EXPECT_EQ(world.error().message.rfind("the cloth touches itself", 0), 0u)
      << world.error().message;
}

TEST(ClothWorld, RefusesBadWorlds) {
  ClothWorldDesc desc = sheet_over_ball();
  desc.ground->height = 0.6;
  EXPECT_EQ(build_cloth_world(desc).error().message, "particle 0 starts on or below the ground");
  desc = sheet_over_ball();
  desc.colliders[0].shape = PlaneShape{};
  EXPECT_EQ(build_cloth_world(desc).error().message,
            "collider 'ball': contact takes no plane collider; give a floor as the scene's "
            "ground");
  desc = sheet_over_ball();
  desc.colliders.push_back(desc.colliders[0]);
  EXPECT_EQ(build_cloth_world(desc).error().message, "two colliders are named 'ball'");
  desc = sheet_over_ball();
  desc.time_step = 0.0;
  EXPECT_EQ(build_cloth_world(desc).error().message,
            "the time step (s) must be between 1e-06 and 10, got 0");
  desc = sheet_over_ball();
  std::get<GridClothOptions>(desc.cloth).rotation = Quat(2, 0, 0, 0);
  EXPECT_EQ(build_cloth_world(desc).error().message, "cloth rotation must be a unit quaternion");
}

}  // namespace
}  // namespace animkit
