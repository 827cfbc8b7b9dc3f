// animkit-viewer: the lab's two scenes live on screen, or captured to a PNG without one.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include "animkit/cloth/integrator_choice.h"
#include "animkit/cloth/integrator_registry.h"
#include "animkit/core/quote.h"
#include "animkit/io/cloth_scene_source.h"
#include "animkit/kinematics/tree_ik_solver.h"
#include "animkit/scene/cloth_scenes.h"
#include "animkit/scene/scene_registry.h"
#include "drawing_args.h"
#include "hosts.h"
#include "size_arg.h"

namespace animkit::viewer {

int report_error(const std::string& message, int code) {
  std::fprintf(stderr, "animkit-viewer: error: %s\n", message.c_str());
  return code;
}

namespace {

// "JOINT:DX,DY,DZ" (--hold), or an error naming the text.
Result<HeldFromStart> parse_hold(const std::string& text) {
  const auto colon = text.rfind(':');
  HeldFromStart held;
  double d[3];
  char tail = 0;
  if (colon == std::string::npos || colon == 0 ||
      std::sscanf(text.c_str() + colon + 1, "%lf,%lf,%lf%c", &d[0], &d[1], &d[2], &tail) != 3 ||
      !std::isfinite(d[0]) || !std::isfinite(d[1]) || !std::isfinite(d[2])) {
    return fail("--hold must be JOINT:DX,DY,DZ (metres from the joint), got " + quote_input(text));
  }
  held.joint = text.substr(0, colon);
  held.offset = Vec3(d[0], d[1], d[2]);
  return held;
}

int run(int argc, char** argv) {
  CLI::App app{
      "animkit-viewer: the lab's inverse-kinematics arm, motion capture with IK and foot "
      "locking, and cloth, live. With --capture it runs headless (no display needed) and writes "
      "a picture."};
  ViewerOptions options;
  std::string scene = "ik", solver = "ccd", integrator(integrator_entry(NewtonSettings{}).name);
  std::string size;
  int frames = 0;
  std::string capture;
  app.add_option("--scene", scene,
                 "Scene to open: one of " + scene_names() +
                     " (cloth: the lab's), a clip FILE.bvh or a cloth scene FILE.json")
      ->capture_default_str();
  BvhViewOptions& bvh = options.bvh;
  bvh.path = ANIMKIT_DATA_DIR "/cmu/131_01.bvh";
  std::vector<std::string> holds;
  app.add_option("--bvh", bvh.path, "BVH: the clip (the CMU walk by default)");
  double scale = 0.0;
  CLI::Option* scale_option = app.add_option(
      "--scale", scale,
      "BVH: metres per file unit (CMU's: 0.056444); default: told from the legs' length, and "
      "printed");
  app.add_option("--limits", bvh.limits_path,
                 "BVH: joint limits JSON file (default: human limits, knees and elbows hinges)");
  app.add_flag("--foot-lock", bvh.scene.foot_locked, "BVH: start on the foot-locked clip");
  bool free_feet = false, no_trails = false;
  app.add_flag("--free-feet", free_feet, "BVH: do not pin the ankles while joints are held");
  app.add_flag("--no-trails", no_trails, "BVH: hide the foot trails");
  app.add_option("--frame", bvh.start_frame, "BVH: frame to start on")->capture_default_str();
  app.add_flag("--close-up", bvh.close_up,
               "BVH: the camera frames the character (else the whole clip's path)");
  app.add_option("--select", bvh.selected, "BVH: joint whose limit is drawn (e.g. LeftKnee)");
  app.add_option("--hold", holds,
                 "BVH: hold JOINT:DX,DY,DZ, the joint at its start position plus this offset "
                 "(metres), as if dragged there (repeatable)");
  apps::DrawingArgs drawing;
  drawing.shape = "star";
  apps::add_drawing_options(app, drawing);
  app.add_option("--solver", solver,
                 "IK: ccd or fabrik; BVH: ccd, fabrik, dls or sdls (default ccd)")
      ->capture_default_str();
  GridClothOptions& grid = options.cloth.grid;
  app.add_option("--grid", grid.cells, "Cloth: cells per side")->capture_default_str();
  app.add_option("--integrator", integrator, "Cloth: " + integrator_names())->capture_default_str();
  app.add_option("--mass", grid.mass, "Cloth: mass per particle")->capture_default_str();
  app.add_option("--stiffness", grid.stiffness, "Cloth: spring stiffness")->capture_default_str();
  app.add_option("--damping", grid.damping, "Cloth: spring damping")->capture_default_str();
  app.add_option("--gravity", grid.gravity, "Cloth: gravity along -y")->capture_default_str();
  app.add_option("--dt", options.cloth.time_step, "Cloth: seconds per step (one per frame)")
      ->capture_default_str();
  app.add_flag("--paused", options.paused, "Start with the scene paused (Space starts it)");
  app.add_flag("--springs", options.cloth_style.springs, "Cloth: draw every spring");
  app.add_flag("--particles", options.cloth_style.particles, "Cloth: draw every particle");
  app.add_flag("--contacts", options.cloth_style.contacts,
               "Cloth: show the contact points (the closest points of every active pair)");
  app.add_option("--frames", frames,
                 "Frames to run before exiting (0: until the window is closed; --capture "
                 "needs at least 1)")
      ->capture_default_str();
  app.add_option("--capture", capture,
                 "Run --frames frames offscreen and write the last one (side panel included) "
                 "to this PNG, then exit; no display needed");
  app.add_option("--size", size, "Window or picture size WIDTHxHEIGHT (default 1280x800)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    return report_error(std::string(e.what()) + " (see animkit-viewer --help)", 2);
  }

  const SceneEntry* scene_entry = find_scene(scene);
  if (scene.ends_with(".bvh")) {
    options.scene = SceneKind::bvh;
    bvh.path = scene;
  } else if (scene_entry && scene_entry->kind != SceneKind::cloth) {
    options.scene = scene_entry->kind;
  } else if (scene == "cloth" || scene == "lab") {
    options.scene = SceneKind::cloth;
  } else {
    // A cloth scene from the registry the CLI uses, or a scene file: it gives the whole world.
    auto world = open_cloth_scene(scene);
    if (!world) {
      return report_error(scene.ends_with(".json")
                              ? world.error().message
                              : "unknown scene " + quote_input(scene) +
                                    " (expected a .bvh or .json file or one of: " + scene_names() +
                                    ")",
                          2);
    }
    for (const char* lab_option :
         {"--grid", "--integrator", "--mass", "--stiffness", "--damping", "--gravity", "--dt"}) {
      if (app.count(lab_option) > 0) {
        return report_error(std::string(lab_option) + " sets the lab's cloth; --scene " +
                                quote_input(scene) +
                                " gives the whole scene (change it in the side panel)",
                            2);
      }
    }
    if (world->choose_integrator) {  // "auto": measured here, before the window opens
      const double tolerance = tolerance_of(world->simulation.integrator).value_or(1e-6);
      auto choice = choose_integrator(*world, tolerance);
      if (!choice) return report_error(choice.error().message, 2);
      world->simulation.integrator = choice->settings;
      world->choose_integrator = false;
    }
    options.scene = SceneKind::cloth;
    options.cloth_world = NamedClothWorld{scene, std::move(*world)};
  }
  bvh.scene.pin_feet = !free_feet;
  bvh.scene.trails = !no_trails;
  for (const std::string& text : holds) {
    auto held = parse_hold(text);
    if (!held) return report_error(held.error().message, 2);
    bvh.held.push_back(*held);
  }
  if (scale_option->count() > 0) {
    if (!(std::isfinite(scale) && scale > 0.0)) {
      return report_error("--scale must be a number > 0 (metres per file unit)", 2);
    }
    bvh.scale = scale;
  }
  if (options.scene == SceneKind::bvh) {
    const auto tree_solver = app.count("--solver") > 0 ? parse_tree_ik_solver(solver)
                                                       : std::optional(BvhSceneOptions{}.solver);
    if (!tree_solver) {
      return report_error(
          "unknown solver '" + solver + "' for the BVH scene (expected fabrik, ccd, dls or sdls)",
          2);
    }
    bvh.scene.solver = *tree_solver;
    solver = "ccd";  // the arm's, should the user switch to it
  }
  const auto ik_solver = parse_ik_solver(solver);
  if (!ik_solver)
    return report_error("unknown solver '" + solver + "' (expected ccd or fabrik)", 2);
  options.ik.solver = *ik_solver;
  const auto request = apps::drawing_request(drawing);
  if (!request) return report_error(request.error().message, 2);
  options.ik.source = request->first;
  options.ik.layout = request->second;
  const IntegratorEntry* entry = find_integrator(integrator);
  if (!entry) {
    return report_error(
        "unknown integrator '" + integrator + "' (expected one of: " + integrator_names() + ")", 2);
  }
  options.cloth.simulation.integrator = entry->defaults;
  if (!size.empty()) {
    const auto parsed = apps::parse_pixel_size(size, 300);
    if (!parsed || parsed->width < 400) {
      return report_error(
          "--size must be WIDTHxHEIGHT between 400x300 and 8192x8192, got '" + size + "'", 2);
    }
    options.width = parsed->width;
    options.height = parsed->height;
  }
  if (frames < 0)
    return report_error("--frames must be 0 or more, got " + std::to_string(frames), 2);
  if (!capture.empty()) {
    if (frames == 0) return report_error("--capture needs --frames N with N >= 1", 2);
    return run_headless(options, frames, capture);
  }
  return run_window(options, frames);
}

}  // namespace
}  // namespace animkit::viewer

int main(int argc, char** argv) {
  try {
    return animkit::viewer::run(argc, argv);
  } catch (const std::exception& e) {
    return animkit::viewer::report_error(e.what(), 1);
  }
}
