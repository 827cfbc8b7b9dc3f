#include "cloth_command.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
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
#include "animkit/io/collider_export.h"
#include "animkit/io/point_cache.h"
#include "animkit/scene/cloth_scene.h"
#include "animkit/scene/cloth_scenes.h"
#include "animkit/scene/collider_drawing.h"
#include "cli_errors.h"
#include "cloth_world_of.h"
#include "run_output.h"

namespace animkit::cli {

namespace {

// "frame 120/600, 1.23 ms/step" on one rewritten line, only when stderr is a terminal.
class ProgressLine {
 public:
  explicit ProgressLine(int total) : total_(total), enabled_(::isatty(::fileno(stderr)) != 0) {}
  void update(int frame, double ms) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (frame < total_ && now - last_ < std::chrono::milliseconds(200)) return;
    last_ = now;
    std::fprintf(stderr, "\rframe %d/%d, %.3f ms/step   ", frame, total_, ms);
    std::fflush(stderr);
  }
  void done() {
    if (enabled_) std::fprintf(stderr, "\n");
  }

 private:
  int total_;
  bool enabled_;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace

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
  const std::vector<Collider>* colliders = &world->colliders;
  // The colliders where the solver has them: on their paths after every converged step, short
  // of them after a step CCD held a collider back (drawn and cached where it really is).
  std::vector<Collider> posed = *colliders;
  const auto solver_colliders = [&]() -> const std::vector<Collider>& {
    for (std::size_t i = 0; world->contact && i < posed.size(); ++i)
      posed[i].set_pose(sim->state().time, world->contact->collider_pose(i));
    return posed;
  };
  const auto solver_collider_points = [&] {
    return world->contact ? world->contact->collider_points()
                          : collider_points(*colliders, sim->state().time);
  };

  // Opened before the run, so a missing OpenGL or ffmpeg stops it before any file is written.
  PictureArgs picture_args = args.pictures;
  picture_args.video = video;
  auto pictures = PictureOutput::open(picture_args, !out.empty(), 1.0 / dt);
  if (!pictures) return report_error(pictures.error().message);
  const ClothPictureFrame framing =
      cloth_picture_frame(*world_desc, *cloth, sim->state(), world->colliders);
  const OrbitCamera camera =
      OrbitCamera::framing(framing.focus, pictures->aspect(), kClothPictureYaw, kClothPicturePitch);
  const double floor_height = framing.floor_height;
  DrawList picture;
  const auto describe_state = [&] {
    picture.clear();
    describe_cloth(picture, sim->model(), sim->state(), {.floor_height = floor_height});
    describe_colliders(picture, solver_colliders());
  };
  if (pictures->take_video_frame()) {
    describe_state();
    if (auto ok = pictures->add_video_frame(picture, camera); !ok)
      return report_error(ok.error().message);
  }

  std::optional<Pc2Writer> cache, collider_cache;
  if (!out.empty()) {
    if (auto ok = ensure_output_directory(out); !ok) return report_error(ok.error().message);
    auto opened = Pc2Writer::open(out / "cloth.pc2", sim->model().particle_count());
    if (!opened) return report_error(opened.error().message);
    cache.emplace(std::move(*opened));
    if (auto ok = cache->add_frame(sim->state().positions); !ok)
      return report_error(ok.error().message);
    // Moving colliders play back beside the cloth: their surfaces, frame by frame.
    if (any_collider_moves(*colliders)) {
      auto opened_colliders =
          Pc2Writer::open(out / "colliders.pc2", collider_point_count(*colliders));
      if (!opened_colliders) return report_error(opened_colliders.error().message);
      collider_cache.emplace(std::move(*opened_colliders));
      if (auto ok = collider_cache->add_frame(solver_collider_points()); !ok)
        return report_error(ok.error().message);
    }
  }

  const ClothState rest = sim->state();  // for the OBJ: the mesh as it starts
  ProgressLine progress(world_desc->frames);
  // Each frame: a point-cache frame, a video frame, the progress line.
  const auto record_frame = [&](int frame, const ClothSimulator& s,
                                const StepReport& step) -> Result<void> {
    if (cache) {
      if (auto ok = cache->add_frame(s.state().positions); !ok) return ok;
    }
    if (collider_cache) {
      if (auto ok = collider_cache->add_frame(solver_collider_points()); !ok) return ok;
    }
    if (pictures->take_video_frame()) {
      describe_state();
      if (auto ok = pictures->add_video_frame(picture, camera); !ok) return ok;
    }
    progress.update(frame, step.ms);
    return {};
  };
  auto run = run_cloth(*sim, world_desc->frames, dt, record_frame);
  if (!run) return report_error(run.error().message);
  const std::vector<StepReport>& steps = run->steps;
  const std::optional<std::string>& divergence = run->divergence;
  progress.done();

  ClothRunInfo info = run_info(*world_desc, *sim, integrator_name, args.scene);
  info.divergence = divergence;
  if (cache) {
    // A diverged run's results are its metrics (where and how it failed) and no animation:
    // the unfinished cache is dropped with its writer.
    if (!divergence) {
      describe_state();
      if (auto ok = pictures->write_png(out / "final.png", picture, camera); !ok) {
        return report_error(ok.error().message);
      }
      if (auto ok = cache->finish(); !ok) return report_error(ok.error().message);
      if (collider_cache) {
        if (auto ok = collider_cache->finish(); !ok) return report_error(ok.error().message);
      }
      if (auto ok = write_file_atomic(out / "cloth.obj", cloth_obj(sim->model(), rest)); !ok) {
        return report_error(ok.error().message);
      }
      // The colliders as Blender opens them beside the cloth, in their first frame's pose.
      if (!colliders->empty()) {
        if (auto ok = write_file_atomic(out / "colliders.obj", colliders_obj(*colliders, 0.0)); !ok)
          return report_error(ok.error().message);
      }
    }
    if (auto ok = write_file_atomic(out / "metrics.json", cloth_metrics_json(info, steps)); !ok) {
      return report_error(ok.error().message);
    }
  }
  if (!divergence) {
    if (auto ok = pictures->finish_video(); !ok) return report_error(ok.error().message);
  }
  // A diverged run's unfinished caches are dropped now: their writers remove their temporaries
  // before the folder is swapped in.
  cache.reset();
  collider_cache.reset();
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
    std::printf("wrote metrics.json, cloth.obj, cloth.pc2 (%d frames)%s to %s\n", s.frames + 1,
                pictures->wants_png() ? ", final.png" : "", args.out.c_str());
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
  cloth->add_option("--scene", args->scene,
                    "A whole scene: a built-in one (" + cloth_scene_names() +
                        ") or a JSON scene file (see the README); --frames, --dt, --integrator, "
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
                        "README for the values)");
  cloth->add_option("--frames", args->frames, "Steps to simulate")->capture_default_str();
  cloth->add_option("--dt", args->dt, "Seconds per step (the frame's duration)")
      ->capture_default_str();
  cloth
      ->add_option("--integrator", args->integrator,
                   "auto (the fastest on this scene, measured over its first 3 steps) or one "
                   "of: " +
                       integrator_names())
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
                    "Folder for metrics.json, cloth.obj, cloth.pc2 and final.png (created if "
                    "needed; replaced whole when the run ends, see the README)");
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
          "--damping", "--gravity", "--sphere", "--ground", "--thickness", "--friction",
          "--no-self-contact", "--wind", "--gust"}) {
      if (cloth->count(option) > 0) args->world_options_given.emplace_back(option);
    }
    return run_cloth(*args);
  };
}

}  // namespace animkit::cli
