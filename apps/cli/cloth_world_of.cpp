#include "cloth_world_of.h"

#include "animkit/cloth/integrator_registry.h"
#include "animkit/cloth/material.h"
#include "animkit/core/quote.h"
#include "animkit/io/cloth_scene_file.h"
#include "animkit/scene/cloth_scenes.h"

namespace animkit::cli {

namespace {

// The grid to simulate: the lab's, or a physical sheet of the --material.
Result<GridClothOptions> grid_of(const ClothArgs& args) {
  GridClothOptions grid = args.grid;
  if (args.material.empty() && !args.material_given) return grid;
  const MaterialPreset* preset = find_material(args.material);
  if (!preset) {
    return fail("unknown material " + quote_input(args.material) +
                " (expected one of: " + material_names() + ")");
  }
  if (!args.lab_options_given.empty()) {
    return fail(args.lab_options_given.front() +
                " sets the lab's per-particle cloth; --material sets masses and stiffnesses "
                "from the material");
  }
  grid.material = preset->material;
  if (!args.gravity_given) grid.gravity = 9.81;
  return grid;
}

// The sheet: the grid, or the --mesh with its pins. Checks the options first.
Result<void> set_cloth(const ClothArgs& args, ClothWorldDesc& world) {
  auto grid = grid_of(args);
  if (!grid) return fail(grid.error().message);
  world.material_name = args.material;
  if (args.mesh.mesh.empty()) {
    if (!args.mesh.pins.empty() || !args.mesh.pin_boxes.empty()) {
      return fail(std::string(args.mesh.pins.empty() ? "--pin-box" : "--pin") +
                  " pins vertices of a --mesh; the grid pins the two corners of its first edge");
    }
    if (auto error = grid->validate()) return fail(error->message);
    world.cloth = *grid;
    return {};
  }
  if (!args.grid_options_given.empty()) {
    return fail(args.grid_options_given.front() +
                " shapes the grid; --mesh gives the cloth's shape and size");
  }
  auto options = mesh_cloth_options(args.mesh, grid->material, grid->mass, grid->stiffness,
                                    grid->damping, grid->gravity);
  if (!options) return fail(options.error().message);
  world.cloth = std::move(*options);
  return {};
}

// A built-in scene's name or a JSON scene file.
Result<ClothWorldDesc> scene_of(const std::string& scene) {
  if (const ClothSceneEntry* entry = find_cloth_scene(scene)) return entry->make();
  if (scene.ends_with(".json")) return read_cloth_scene(scene);
  return fail("unknown scene " + quote_input(scene) +
              " (expected a .json file or one of: " + cloth_scene_names() + ")");
}

}  // namespace

Result<ClothWorldDesc> world_of(const ClothArgs& args) {
  ClothWorldDesc world;
  if (args.given("--scene") && args.scene.empty())
    return fail("--scene needs a built-in scene's name or a .json file, got ''");
  // Options that only mean something beside another, refused rather than ignored (with
  // --scene they are refused below: the scene gives the world whole).
  const bool contact = args.given("--sphere") || args.given("--box") || args.given("--capsule") ||
                       args.given("--ground");
  for (const char* option : {"--thickness", "--friction", "--no-self-contact"}) {
    if (!args.given("--scene") && args.given(option) && !contact) {
      return fail(std::string(option) +
                  " applies to contact: give a collider (--sphere, --box, --capsule) or --ground "
                  "too");
    }
  }
  if (!args.given("--scene") && args.given("--gust") && !args.given("--wind"))
    return fail("--gust adds gusts to a wind: give --wind too (--wind 0,0,0 for gusts alone)");
  if (!args.scene.empty()) {
    if (!args.world_options_given.empty()) {
      return fail(args.world_options_given.front() +
                  " describes the cloth or its world, which --scene gives whole");
    }
    auto scene = scene_of(args.scene);
    if (!scene) return fail(scene.error().message);
    world = std::move(*scene);
  } else {
    if (auto ok = set_cloth(args, world); !ok) return fail(ok.error().message);
    if (auto ok = apply_world_args(args.world, world); !ok) return fail(ok.error().message);
  }
  const bool scene = !args.scene.empty();
  if (!scene || args.given("--frames")) world.frames = args.frames;
  if (!scene || args.given("--dt")) world.time_step = args.dt;
  if (!scene || args.given("--substeps")) world.simulation.substeps = args.substeps;
  // "auto" is resolved by the run, which measures; here the registry's settings.
  if ((!scene || args.given("--integrator")) && args.integrator != "auto") {
    const IntegratorEntry* integrator = find_integrator(args.integrator);
    if (!integrator) {
      return fail("unknown integrator " + quote_input(args.integrator) +
                  " (expected auto or one of: " + integrator_names() + ")");
    }
    const std::optional<double> tolerance = tolerance_of(world.simulation.integrator);
    world.simulation.integrator = integrator->defaults;
    if (tolerance) set_tolerance(world.simulation.integrator, *tolerance);
  }
  if (!scene || args.given("--tolerance"))
    set_tolerance(world.simulation.integrator, args.tolerance);
  // A world of options with contact or a material solves as the built-in contact scenes do
  // unless the solver is chosen: the lab's defaults (CG, 1e-6) are many times slower there.
  if (!scene && world.fast_by_default() && !args.given("--integrator") &&
      !args.given("--tolerance"))
    use_fast_settings(world);
  return world;
}

ClothRunInfo run_info(const ClothWorldDesc& world, const ClothSimulator& sim,
                      const std::string& integrator, const std::string& scene) {
  ClothRunInfo info;
  info.integrator = integrator;
  info.scene = scene;
  info.particles = sim.model().particle_count();
  info.springs = sim.model().spring_count();
  info.dt = world.time_step;
  info.substeps = sim.options().effective_substeps();
  info.tolerance = tolerance_of(world.simulation.integrator).value_or(0.0);
  info.material = world.material_name;
  if (const auto* grid = std::get_if<GridClothOptions>(&world.cloth)) {
    info.grid = grid->cells;
    info.size = grid->size;
    info.mass = grid->mass;
    info.stiffness = grid->stiffness;
    info.damping = grid->damping;
    info.gravity = grid->gravity;
  } else {
    const auto& mesh = std::get<MeshClothOptions>(world.cloth);
    info.mass = mesh.mass;
    info.stiffness = mesh.stiffness;
    info.damping = mesh.damping;
    info.gravity = mesh.gravity;
  }
  return info;
}

}  // namespace animkit::cli
