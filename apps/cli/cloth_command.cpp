#include "cloth_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "animkit/cloth/cloth_run.h"
#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/integrator_choice.h"
#include "animkit/cloth/material.h"
#include "animkit/cloth/mesh_cloth.h"
#include "animkit/cloth/parameter_ranges.h"
#include "animkit/core/quote.h"
#include "animkit/core/validation.h"
#include "animkit/io/atomic_write.h"
#include "animkit/io/cloth_report.h"
#include "animkit/io/gltf_sink.h"
#include "animkit/io/metrics_sink.h"
#include "animkit/io/obj_sink.h"
#include "animkit/io/point_cache_sink.h"
#include "animkit/scene/cloth_scene.h"
#include "animkit/scene/cloth_scenes.h"
#include "cli_errors.h"
#include "cloth_picture_sink.h"
#include "cloth_world_of.h"
#include "progress_line.h"
#include "run_output.h"

namespace animkit::cli {

std::string material_names() {
  std::string names;
  for (const MaterialPreset& preset : material_presets())
    names += (names.empty() ? "" : ", ") + std::string(preset.name);
  return names;
}

namespace {

// "auto: implicit-pcg 1.2 ms/step, ... -> implicit-multigrid": what the trial measured.
void print_integrator_trial(const IntegratorChoice& choice) {
  std::printf("auto:");
  for (const IntegratorTrial& trial : choice.trials) {
    std::printf(" %.*s ", static_cast<int>(trial.name.size()), trial.name.data());
    if (trial.diverged) {
      std::printf("diverged;");
    } else {
      std::printf("%.3f ms/step over %d step%s%s;", trial.ms_per_step, trial.steps,
                  trial.steps == 1 ? "" : "s", trial.converged ? "" : " (not converged)");
    }
  }
  std::printf(" chose %.*s\n", static_cast<int>(choice.name.size()), choice.name.data());
}

}  // namespace

int run_cloth_in(const ClothArgs& args, const std::filesystem::path& out, const std::string& video,
                 const std::function<Result<void>()>& commit) {
  if (!kTimeStepRange.contains(args.dt)) {
    return report_error(kTimeStepRange.refusal("--dt (seconds)", args.dt));
  }
  if (args.frames < 1 || args.frames > kMaxWorldFrames) {
    return report_error("--frames must be between 1 and " + std::to_string(kMaxWorldFrames) +
                        ", got " + std::to_string(args.frames));
  }
  auto world_desc = world_of(args);
  if (!world_desc) return report_error(world_desc.error().message);
  // The lab's parameters are per particle and per spring: a finer grid of them is a heavier,
  // stretchier sheet (at --grid 40 it hangs 1.9 times its length). Said, since the sheet still
  // looks like cloth while not being the lab's.
  if (const auto* grid = std::get_if<GridClothOptions>(&world_desc->cloth);
      grid && !grid->material && args.scene.empty() && grid->cells > GridClothOptions{}.cells) {
    std::fprintf(stderr,
                 "animkit: note: the lab's mass and stiffness are per particle and spring, so "
                 "%d x %d particles make a heavier, stretchier sheet than the lab's 11 x 11; "
                 "--material (e.g. cotton) gives one whose behaviour does not depend on --grid\n",
                 grid->cells + 1, grid->cells + 1);
  }
  const auto cloth = build_world_cloth(*world_desc);
  if (!cloth) return report_error(cloth.error().message);
  const double dt = world_desc->time_step;
  const bool choose = args.given("--integrator") ? args.integrator == "auto"
                      : args.scene.empty()       ? args.integrator == "auto"
                                                 : world_desc->choose_integrator;
  if (choose) {
    const double tolerance =
        tolerance_of(world_desc->simulation.integrator).value_or(args.tolerance);
    auto choice = choose_integrator(*world_desc, tolerance);
    if (!choice) return report_error(choice.error().message);
    print_integrator_trial(*choice);
    world_desc->simulation.integrator = choice->settings;
  }
  const std::string integrator_name(integrator_entry(world_desc->simulation.integrator).name);
  auto world = build_cloth_world(*world_desc);
  if (!world) return report_error(world.error().message);
  ClothSimulator* sim = &world->simulator;

  // Opened before the run, so a missing OpenGL or ffmpeg stops it before any file is written.
  PictureArgs picture_args = args.pictures;
  picture_args.video = video;
  auto pictures = PictureOutput::open(picture_args, !out.empty(), 1.0 / dt);
  if (!pictures) return report_error(pictures.error().message);
  const ClothPictureFrame framing =
      cloth_picture_frame(*world_desc, *cloth, sim->state(), world->colliders);

  // The outputs, each a sink of the run: written whole at its end, or (a diverged run) only
  // the metrics that say where it failed.
  ClothRunInfo info = run_info(*world_desc, *sim, integrator_name, args.scene);
  std::optional<PointCacheSink> point_cache;
  std::optional<ObjSink> meshes;
  std::optional<GltfSink> gltf;
  std::optional<MetricsSink> metrics;
  std::vector<ClothSink*> sinks;
  if (!out.empty()) {
    if (auto ok = ensure_output_directory(out); !ok) return report_error(ok.error().message);
    sinks.push_back(&point_cache.emplace(out));
    sinks.push_back(&meshes.emplace(out));
    // A run longer than a .glb holds keeps its point cache and says why it has no glTF.
    std::optional<Error> too_long;
    if (!args.no_gltf)
      too_long = cloth_glb_fits(sim->model().particle_count(), world_desc->frames + 1LL);
    if (too_long) {
      std::fprintf(stderr, "animkit: warning: no cloth.glb: %s (cloth.pc2 holds every frame)\n",
                   too_long->message.c_str());
    } else if (!args.no_gltf) {
      sinks.push_back(&gltf.emplace(out / "cloth.glb"));
    }
  }
  ClothPictureSink picture_sink(
      *pictures, framing, pictures->wants_png() ? std::optional(out / "final.png") : std::nullopt);
  sinks.push_back(&picture_sink);
  if (!out.empty()) sinks.push_back(&metrics.emplace(out, info));
  ProgressLine progress;
  sinks.push_back(&progress);

  auto run = run_cloth(*world, world_desc->frames, dt, sinks);
  if (!run) return report_error(run.error().message);
  const std::vector<StepReport>& steps = run->steps;
  const std::optional<std::string>& divergence = run->divergence;
  // The sinks hold no temporaries now: finished, or (a diverged run) dropped.
  if (auto ok = commit(); !ok) return report_error(ok.error().message);
  if (divergence) return report_error(*divergence);

  const ClothRunSummary s = summarize(steps);
  std::printf("%-15s %6s %9s %7s %12s %12s %10s %9s %13s\n", "integrator", "frames", "particles",
              "springs", "ms/step med", "newton mean", "cg mean", "converged", "final energy");
  std::printf("%-15s %6d %9d %7d %12.3f %12.2f %10.1f %8.1f%% %13.6g\n", info.integrator.c_str(),
              s.frames, info.particles, info.springs, s.ms_per_step_median,
              s.newton_iterations_mean, s.linear_iterations_mean, 100.0 * s.converged_fraction,
              s.final_energy);
  if (!args.out.empty()) {
    std::printf("wrote metrics.json, cloth.obj, cloth.pc2 (%d frames)%s%s to %s\n", s.frames + 1,
                gltf ? ", cloth.glb" : "", pictures->wants_png() ? ", final.png" : "",
                args.out.c_str());
  }
  if (!args.pictures.video.empty()) std::printf("wrote %s\n", args.pictures.video.c_str());
  // Results, but not what the tolerance promised: said where it cannot be missed.
  const long unconverged = std::count_if(steps.begin(), steps.end(),
                                         [](const StepReport& step) { return !step.converged; });
  if (unconverged > 0) {
    std::fprintf(stderr,
                 "animkit: warning: %ld of %d steps stopped short of the tolerance (the solver's "
                 "iteration cap)\n",
                 unconverged, s.frames);
  }
  return 0;
}

int run_cloth(const ClothArgs& args) {
  std::string video = args.pictures.video;
  auto output = RunOutput::begin(args.out, video);
  if (!output) return report_error(output.error().message);
  return run_cloth_in(args, output->dir(), video, [&] { return output->commit(); });
}

std::function<int()> add_cloth_command(CLI::App& app) {
  auto args = std::make_shared<ClothArgs>();
  CLI::App* cloth = app.add_subcommand(
      "cloth",
      "Simulates the lab's mass-spring cloth (an (N+1) x (N+1) grid pinned at two "
      "corners) and reports what each step did; --out writes metrics and an animation "
      "Blender opens (cloth.obj + cloth.pc2 for the Mesh Cache modifier).");
  cloth->add_option(
      "--scene", args->scene,
      "A whole scene: a built-in one (" + cloth_scene_names() +
          ") or a JSON scene file (see docs/contact.md); --frames, --dt, --integrator, "
          "--tolerance and --substeps may replace its own");
  cloth->add_option("--grid", args->grid.cells, "Cells per side N (N + 1 particles per side)")
      ->capture_default_str();
  cloth->add_option("--size", args->grid.size, "Side of the square sheet (m with --material)")
      ->capture_default_str();
  cloth->add_option("--mesh", args->mesh.mesh,
                    "An OBJ file: the cloth's shape at rest instead of the grid (particles at its "
                    "vertices, springs on its edges; pin with --pin or --pin-box)");
  cloth->add_option("--pin", args->mesh.pins,
                    "With --mesh: vertices to pin, I,J,... counted from 0 (repeatable)");
  cloth->add_option("--pin-box", args->mesh.pin_boxes,
                    "With --mesh: pins every vertex inside the box X0,Y0,Z0,X1,Y1,Z1 (repeatable)");
  cloth->add_option("--material", args->material,
                    "A physical sheet of: " + material_names() +
                        " (masses and stiffnesses from the material, gravity 9.81; see the "
                        "docs/materials.md for the values)");
  cloth->add_option("--frames", args->frames, "Steps to simulate")->capture_default_str();
  cloth->add_option("--dt", args->dt, "Seconds per step (the frame's duration)")
      ->capture_default_str();
  cloth
      ->add_option("--integrator", args->integrator,
                   "auto (the fastest on this scene, measured over its first 3 steps) or one "
                   "of: " +
                       integrator_names() +
                       "; with a collider, --ground or --material and neither this nor "
                       "--tolerance, the fast settings (docs/contact.md)")
      ->capture_default_str();
  cloth
      ->add_option("--substeps", args->substeps,
                   "Substeps per step; 0 = the integrator's default (explicit 1000, implicit 1)")
      ->capture_default_str();
  cloth->add_option("--mass", args->grid.mass, "Mass per particle (> 0; lab range 0.5..10)")
      ->capture_default_str();
  cloth
      ->add_option("--stiffness", args->grid.stiffness, "Spring stiffness (> 0; lab range 10..300)")
      ->capture_default_str();
  cloth->add_option("--damping", args->grid.damping, "Spring damping (>= 0; lab range 0.1..10)")
      ->capture_default_str();
  cloth->add_option("--gravity", args->grid.gravity, "Gravity along -y (lab range 0.1..1)")
      ->capture_default_str();
  cloth
      ->add_option("--tolerance", args->tolerance,
                   "Newton stops when the gradient norm is this fraction of its start (0..1)")
      ->capture_default_str();
  add_world_options(*cloth, args->world);
  cloth->add_option("--out", args->out,
                    "Folder for metrics.json, cloth.obj, cloth.pc2, cloth.glb and final.png "
                    "(created if needed; replaced whole when the run ends, see docs/errors.md)");
  cloth->add_flag("--no-gltf", args->no_gltf,
                  "No cloth.glb (glTF 2.0: the sheet and colliders with every frame, for web "
                  "viewers, three.js, Godot, Unity and Blender) in the --out folder");
  add_picture_options(*cloth, args->pictures, "final.png");
  return [args, cloth] {
    args->gravity_given = cloth->count("--gravity") > 0;
    args->material_given = cloth->count("--material") > 0;
    for (const CLI::Option* option : cloth->get_options()) {
      if (option->count() > 0) args->options_given.push_back(option->get_name());
    }
    for (const char* option : {"--mass", "--stiffness", "--damping"}) {
      if (cloth->count(option) > 0) args->lab_options_given.emplace_back(option);
    }
    for (const char* option : {"--grid", "--size"}) {
      if (cloth->count(option) > 0) args->grid_options_given.emplace_back(option);
    }
    for (const char* option :
         {"--grid", "--size", "--mesh", "--pin", "--pin-box", "--material", "--mass", "--stiffness",
          "--damping", "--gravity", "--sphere", "--box", "--capsule", "--ground", "--thickness",
          "--friction", "--no-self-contact", "--wind", "--gust"}) {
      if (cloth->count(option) > 0) args->world_options_given.emplace_back(option);
    }
    return run_cloth(*args);
  };
}

}  // namespace animkit::cli
