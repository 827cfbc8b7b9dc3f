// JSON cloth scenes: every key read into the ClothWorldDesc, defaults where absent, and one
// clear error per kind of mistake.
#include "animkit/io/cloth_scene_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../support/temp_files.h"
#include "animkit/cloth/integrator_registry.h"

namespace animkit {
namespace {

Result<ClothWorldDesc> parse(const std::string& text) {
  return parse_cloth_scene(text, "scene.json", std::filesystem::current_path());
}

TEST(ClothSceneFile, AnEmptyObjectIsTheLabsScene) {
  const auto scene = parse("{}");
  ASSERT_TRUE(scene) << scene.error().message;
  const auto& grid = std::get<GridClothOptions>(scene->cloth);
  EXPECT_EQ(grid.cells, 10);
  EXPECT_EQ(grid.pins, GridPins::corners);
  EXPECT_TRUE(scene->colliders.empty());
  EXPECT_FALSE(scene->ground);
  EXPECT_FALSE(scene->air);
  EXPECT_EQ(scene->frames, 300);
  EXPECT_DOUBLE_EQ(scene->time_step, 1.0 / 60.0);
}

TEST(ClothSceneFile, ReadsEveryPart) {
  const auto scene = parse(R"({
    "cloth": {"grid": 20, "size": 1.5, "height": 0.9, "pins": "none", "material": "cotton",
              "rotation": {"axis": [1, 0, 0], "degrees": 90}, "offset": [-0.75, 0, 0]},
    "colliders": [
      {"name": "ball", "shape": "sphere", "radius": 0.3, "position": [0, 0.3, 0],
       "angular_velocity": [0, 2, 0], "friction": 0.6},
      {"name": "table", "shape": "box", "half_extents": [0.4, 0.1, 0.4],
       "keyframes": [{"time": 0, "position": [0, 0, 0]},
                     {"time": 1, "position": [0, 0.5, 0],
                      "rotation": {"axis": [0, 1, 0], "degrees": 45}}]},
      {"shape": "capsule", "radius": 0.1, "half_length": 0.2, "position": [2, 0, 0]}],
    "ground": {"height": -0.1, "friction": 0.4},
    "contact": {"thickness": 0.004, "self_contact": false, "self_friction": 0.2,
                "friction_passes": 2, "hessian": "gauss_newton"},
    "wind": {"velocity": [3, 0, 0], "gust": [1, 0, 0], "gust_frequency": 0.25},
    "solver": {"integrator": "implicit-multigrid", "tolerance": 1e-4},
    "dt": 0.02, "frames": 12})");
  ASSERT_TRUE(scene) << scene.error().message;
  const auto& grid = std::get<GridClothOptions>(scene->cloth);
  EXPECT_EQ(grid.cells, 20);
  EXPECT_EQ(grid.pins, GridPins::none);
  ASSERT_TRUE(grid.material);
  EXPECT_EQ(scene->material_name, "cotton");
  EXPECT_DOUBLE_EQ(grid.gravity, 9.81);  // a material's default
  EXPECT_NEAR((grid.rotation * Vec3::UnitY() - Vec3::UnitZ()).norm(), 0.0, 1e-15);
  EXPECT_EQ(grid.offset, Vec3(-0.75, 0, 0));
  ASSERT_EQ(scene->colliders.size(), 3u);
  EXPECT_EQ(scene->colliders[0].name, "ball");
  EXPECT_DOUBLE_EQ(std::get<SphereShape>(scene->colliders[0].shape).radius, 0.3);
  EXPECT_EQ(std::get<ScriptedMotion>(scene->colliders[0].motion).angular_velocity, Vec3(0, 2, 0));
  EXPECT_DOUBLE_EQ(scene->colliders[0].friction, 0.6);
  const auto& keys = std::get<KeyframedMotion>(scene->colliders[1].motion).keyframes;
  ASSERT_EQ(keys.size(), 2u);
  EXPECT_EQ(keys[1].position, Vec3(0, 0.5, 0));
  EXPECT_EQ(scene->colliders[2].name, "colliders[2]");  // unnamed: named by its place
  ASSERT_TRUE(scene->ground);
  EXPECT_DOUBLE_EQ(scene->ground->friction, 0.4);
  EXPECT_DOUBLE_EQ(scene->contact.thickness, 0.004);
  EXPECT_FALSE(scene->contact.self_contact);
  EXPECT_EQ(scene->contact.hessian, BarrierHessian::gauss_newton);
  EXPECT_DOUBLE_EQ(scene->self_friction, 0.2);
  EXPECT_EQ(scene->friction_passes, 2);
  ASSERT_TRUE(scene->air);
  EXPECT_EQ(scene->air->wind.velocity, Vec3(3, 0, 0));
  EXPECT_DOUBLE_EQ(*tolerance_of(scene->simulation.integrator), 1e-4);
  EXPECT_EQ(std::get<NewtonSettings>(scene->simulation.integrator).linear_solver,
            LinearSolverKind::multigrid);
  EXPECT_DOUBLE_EQ(scene->time_step, 0.02);
  EXPECT_EQ(scene->frames, 12);
}

TEST(ClothSceneFile, ReadsAMeshClothAndAMeshColliderBesideTheFile) {
  const auto dir = testing_support::fresh_dir("cloth_scene_mesh");
  const std::string quad = "v 0 1 0\nv 1 1 0\nv 1 1 1\nv 0 1 1\nf 1 2 3 4\n";
  std::ofstream(dir / "sheet.obj") << quad;
  std::ofstream(dir / "body.obj") << "v 0 0 0\nv 1 0 0\nv 0 0 1\nv 0 -1 0\n"
                                  << "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
  std::ofstream(dir / "scene.json") << R"({"cloth": {"mesh": "sheet.obj", "pin": [0, 1]},
    "colliders": [{"shape": "mesh", "mesh": "body.obj", "position": [0, -1, 0]}]})";
  const auto scene = read_cloth_scene(dir / "scene.json");
  ASSERT_TRUE(scene) << scene.error().message;
  const auto& mesh = std::get<MeshClothOptions>(scene->cloth);
  EXPECT_EQ(mesh.mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.pins, (std::vector<int>{0, 1}));
  EXPECT_EQ(std::get<MeshShape>(scene->colliders[0].shape).mesh.triangles.size(), 4u);
}

TEST(ClothSceneFile, ReadsTheVelocityToleranceTheLinearForcingAndTheProjection) {
  const auto scene = parse(
      R"({"solver": {"integrator": "implicit-multigrid", "velocity_tolerance": 1e-3,
                     "linear_forcing": 0.1, "projection": "always"},
          "contact": {"hessian": "adaptive"}})");
  ASSERT_TRUE(scene) << scene.error().message;
  const auto& newton = std::get<NewtonSettings>(scene->simulation.integrator);
  EXPECT_EQ(newton.velocity_tolerance, 1e-3);
  EXPECT_EQ(newton.linear_forcing, 0.1);
  EXPECT_EQ(newton.projection, HessianProjection::always);
  const auto exact_first =
      parse(R"({"solver": {"integrator": "implicit-pcg", "projection": "when_indefinite"}})");
  ASSERT_TRUE(exact_first) << exact_first.error().message;
  EXPECT_EQ(std::get<NewtonSettings>(exact_first->simulation.integrator).projection,
            HessianProjection::when_indefinite);
  EXPECT_EQ(scene->contact.hessian, BarrierHessian::adaptive);
}

// The fast settings (use_fast_settings): Newton, multigrid, 1e-4 or the velocity stop at
// 1e-3, CG to 10%, the projected Hessian at once with contact.
void expect_fast_settings(const ClothWorldDesc& world) {
  const auto* newton = std::get_if<NewtonSettings>(&world.simulation.integrator);
  ASSERT_NE(newton, nullptr);
  EXPECT_EQ(newton->linear_solver, LinearSolverKind::multigrid);
  EXPECT_EQ(newton->tolerance, 1e-4);
  EXPECT_EQ(newton->velocity_tolerance, 1e-3);
  EXPECT_EQ(newton->linear_forcing, 0.1);
  EXPECT_EQ(newton->projection, HessianProjection::with_terms);
}

TEST(ClothSceneFile, WithoutASolverContactSolvesWithTheFastSettings) {
  // A ball and no "solver": the built-in contact scenes' settings, not the lab's CG to 1e-6.
  const auto ball = parse(R"({"colliders": [{"radius": 0.1}]})");
  ASSERT_TRUE(ball) << ball.error().message;
  expect_fast_settings(*ball);
  EXPECT_EQ(ball->contact.hessian, BarrierHessian::adaptive);
  // The contact's own "hessian" still applies; so does a solver given.
  const auto projected = parse(R"({"ground": {}, "contact": {"hessian": "projected"}})");
  ASSERT_TRUE(projected) << projected.error().message;
  expect_fast_settings(*projected);
  EXPECT_EQ(projected->contact.hessian, BarrierHessian::projected);
  const auto pcg = parse(R"({"ground": {}, "solver": {"integrator": "implicit-pcg"}})");
  ASSERT_TRUE(pcg) << pcg.error().message;
  EXPECT_EQ(integrator_entry(pcg->simulation.integrator).name, "implicit-pcg");
  // No contact: the lab's solver.
  const auto lab = parse("{}");
  ASSERT_TRUE(lab) << lab.error().message;
  EXPECT_EQ(integrator_entry(lab->simulation.integrator).name,
            integrator_entry(ClothWorldDesc{}.simulation.integrator).name);
  EXPECT_EQ(tolerance_of(lab->simulation.integrator),
            tolerance_of(ClothWorldDesc{}.simulation.integrator));
}

TEST(ClothSceneFile, WithoutASolverAPhysicalSheetSolvesWithTheFastSettings) {
  // A material and nothing to touch: the fast settings too (a hanging cotton sheet at 101 x
  // 101 took 1.5 s a step with the lab's CG to 1e-6); a solver given still wins.
  const auto cotton = parse(R"({"cloth": {"grid": 8, "material": "cotton"}})");
  ASSERT_TRUE(cotton) << cotton.error().message;
  EXPECT_TRUE(cotton->is_physical());
  expect_fast_settings(*cotton);
  const auto pcg =
      parse(R"({"cloth": {"material": "cotton"}, "solver": {"integrator": "implicit-pcg"}})");
  ASSERT_TRUE(pcg) << pcg.error().message;
  EXPECT_EQ(integrator_entry(pcg->simulation.integrator).name, "implicit-pcg");
  const auto lab = parse(R"({"cloth": {"grid": 8}})");
  ASSERT_TRUE(lab) << lab.error().message;
  EXPECT_FALSE(lab->fast_by_default());
  EXPECT_EQ(integrator_entry(lab->simulation.integrator).name,
            integrator_entry(ClothWorldDesc{}.simulation.integrator).name);
}

TEST(ClothSceneFile, TheDocumentedExampleSceneReadsAndBuilds) {
  const auto scene = read_cloth_scene(ANIMKIT_SOURCE_DIR "/docs/scenes/pillow-drop.json");
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(scene->colliders.size(), 2u);
  EXPECT_EQ(scene->frames, 60);
  const auto world = build_cloth_world(*scene);
  EXPECT_TRUE(world) << world.error().message;
}

struct BadScene {
  std::string text, message;
};

class ClothSceneFileErrors : public ::testing::TestWithParam<BadScene> {};

TEST_P(ClothSceneFileErrors, NameTheKeyAndTheProblem) {
  const auto scene = parse(GetParam().text);
  ASSERT_FALSE(scene);
  EXPECT_EQ(scene.error().message, "scene.json: " + GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ClothSceneFileErrors,
    ::testing::Values(
        BadScene{"",
                 "not valid JSON ([json.exception.parse_error.101] parse error at line 1, "
                 "column 1: syntax error while parsing value - unexpected end of input; "
                 "expected '[', '{', or a literal)"},
        BadScene{"[]", "the scene: expected an object {...}, got an array"},
        BadScene{R"({"frame": 3})",
                 "the scene: unknown key 'frame' (this object takes: cloth, colliders, contact, "
                 "dt, frames, ground, solver, wind)"},
        BadScene{R"({"cloth": {"grid": 1.5}})",
                 "cloth.grid: expected a whole number, got a number"},
        BadScene{R"({"cloth": {"material": "tweed"}})",
                 "cloth.material: unknown material preset 'tweed'"},
        BadScene{R"({"cloth": {"material": "silk", "mass": 2}})",
                 "cloth.mass: the material sets masses, stiffnesses and damping"},
        BadScene{R"({"cloth": {"pins": "all"}})",
                 "cloth.pins: expected corners, edge or none, got 'all'"},
        BadScene{R"({"contact": {"hessian": "exact"}})",
                 "contact.hessian: expected one of projected, gauss_newton, adaptive, got 'exact'"},
        BadScene{R"({"colliders": [{"shape": "cube"}]})",
                 "colliders[0].shape: expected sphere, box, capsule or mesh, got 'cube'"},
        BadScene{R"({"colliders": [{"radius": "big"}]})",
                 "colliders[0].radius: expected a number, got the string 'big'"},
        BadScene{R"({"colliders": [{"position": [0, 1]}]})",
                 "colliders[0].position: expected three numbers [x, y, z], got an array"},
        BadScene{R"({"colliders": [{"rotation": {"axis": [0, 0, 0], "degrees": 3}}]})",
                 "colliders[0].rotation: the rotation's axis must not be zero"},
        BadScene{R"({"colliders": [{"radius": -1}]})",
                 "collider 'colliders[0]': radius must be > 0, got -1"},
        BadScene{R"({"colliders": [{"keyframes": [{"time": 0}], "velocity": [1, 0, 0]}]})",
                 "colliders[0].velocity: give either keyframes or a pose"},
        BadScene{R"({"colliders": [{"shape": "mesh", "mesh": "missing.obj"}]})",
                 "colliders[0].mesh: " +
                     (std::filesystem::current_path() / "missing.obj").string() + ": no such file"},
        BadScene{R"({"ground": {"friction": -1}})",
                 "the ground's friction must be between 0 and 10, got -1"},
        BadScene{R"({"frames": 3, "frames": 1000000})",
                 "the key 'frames' appears twice in one object (which one was meant?)"},
        BadScene{R"({"cloth": {"grid": 4, "size": 1, "grid": 5}})",
                 "the key 'grid' appears twice in one object (which one was meant?)"},
        BadScene{R"({"colliders": [{"velocity": [1e300, 0, 0]}]})",
                 "collider 'colliders[0]': linear velocity must have each coordinate between "
                 "-1e+06 and 1e+06, got (1e+300, 0, 0)"},
        BadScene{R"({"colliders": [{"position": [0, 1e300, 0]}]})",
                 "collider 'colliders[0]': initial position must have each coordinate between "
                 "-1e+06 and 1e+06, got (0, 1e+300, 0)"},
        BadScene{R"({"colliders": [{"angular_velocity": [0, 1e300, 0]}]})",
                 "collider 'colliders[0]': angular velocity must have each coordinate between "
                 "-1e+06 and 1e+06, got (0, 1e+300, 0)"},
        BadScene{R"({"colliders": [{"friction": 1e300}]})",
                 "collider 'colliders[0]': friction must be between 0 and 10, got 1e+300"},
        BadScene{R"({"colliders": [{"keyframes": [{"time": 1e300}]}]})",
                 "collider 'colliders[0]': keyframe 0 time (s) must be between -1e+06 and "
                 "1e+06, got 1e+300"},
        BadScene{R"({"ground": {}, "contact": {"stiffness": 1e300}})",
                 "contact stiffness (J/m^4, 0: automatic) must be between 0 and 1e+20, got "
                 "1e+300"},
        BadScene{R"({"solver": {"integrator": "rk4"}})",
                 "solver.integrator: unknown integrator 'rk4' (expected auto or one of: " +
                     integrator_names() + ")"},
        BadScene{R"({"solver": {"integrator": "auto", "velocity_tolerance": 1e-3}})",
                 "solver.velocity_tolerance: applies to a named Newton integrator, not 'auto'"},
        BadScene{R"({"solver": {"integrator": "vbd", "velocity_tolerance": 1e-3}})",
                 "solver.velocity_tolerance: applies to the Newton integrators (implicit-*) "
                 "only, not 'vbd'"},
        BadScene{R"({"solver": {"integrator": "implicit-pcg", "velocity_tolerance": -1}})",
                 "velocity tolerance must be in [0, 1), got -1"},
        BadScene{R"({"solver": {"integrator": "vbd", "linear_forcing": 0.1}})",
                 "solver.linear_forcing: applies to the Newton integrators (implicit-*) "
                 "only, not 'vbd'"},
        BadScene{R"({"solver": {"integrator": "implicit-pcg", "linear_forcing": 1}})",
                 "linear forcing must be in [0, 1), got 1"},
        BadScene{R"({"solver": {"integrator": "implicit-pcg", "projection": "never"}})",
                 "solver.projection: expected one of when_indefinite, always, with_terms, got "
                 "'never'"},
        BadScene{R"({"solver": {"integrator": "vbd", "projection": "always"}})",
                 "solver.projection: applies to the Newton integrators (implicit-*) only, not "
                 "'vbd'"},
        BadScene{R"({"solver": {"integrator": "auto", "projection": "always"}})",
                 "solver.projection: applies to a named Newton integrator, not 'auto'"},
        BadScene{R"({"dt": 1e400})",
                 "not valid JSON ([json.exception.out_of_range.406] number overflow parsing "
                 "'1e400')"},
        BadScene{R"({"frames": 0})", "frames must be between 1 and 1000000, got 0"}));

}  // namespace
}  // namespace animkit
