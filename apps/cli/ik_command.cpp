#include "ik_command.h"

#include <cstdio>
#include <memory>
#include <string>

#include "animkit/core/validation.h"
#include "animkit/io/atomic_write.h"
#include "animkit/io/ik_report.h"
#include "animkit/kinematics/chain.h"
#include "animkit/kinematics/drawing_session.h"
#include "animkit/trajectory/lab_shapes.h"
#include "cli_errors.h"
#include "ik_pictures.h"
#include "ik_table.h"

namespace animkit::cli {

namespace {

struct IkArgs {
  std::string shape = "circle";
  std::string solver = "ccd";
  int max_iterations = IkOptions{}.max_iterations;
  double tolerance = IkOptions{}.tolerance;
  int laps = 1;
  bool cold_start = false;
  std::string fabrik_rotations = "rest";
  std::string target;
  std::string out;
  PictureArgs pictures;
};

std::string shape_names() {
  std::string names;
  for (LabShape s : all_lab_shapes())
    names += (names.empty() ? "" : ", ") + std::string(to_string(s));
  return names;
}

void print_single_target(const Chain& chain, IkSolverKind solver, const DrawingRun& run) {
  const DrawingFrame& frame = run.frames.front();
  const IkResult& result = frame.ik;
  std::printf("solver       %s\n", std::string(to_string(solver)).c_str());
  std::printf("target       %s\n", to_string(frame.target).c_str());
  std::printf("end effector %s\n", to_string(frame.end_effector).c_str());
  std::printf("iterations   %d\n", result.iterations);
  std::printf("error        %.3e\n", result.error);
  std::printf("converged    %s\n", result.converged ? "yes" : "no");
  std::printf("reachable    %s%s\n", result.reachable ? "yes" : "no",
              result.reachable ? "" : " (the arm points straight at the target)");
  for (int i = 0; i < chain.joint_count(); ++i) {
    std::printf("joint %d      %s\n", i, to_string(run.final_pose.global_positions[i]).c_str());
  }
}

int run(const IkArgs& args) {
  const auto shape = parse_lab_shape(args.shape);
  if (!shape) {
    return report_error("unknown shape '" + args.shape + "' (expected one of: " + shape_names() +
                        ")");
  }
  const auto solver = parse_ik_solver(args.solver);
  if (!solver) return report_error("unknown solver '" + args.solver + "' (expected ccd or fabrik)");

  const auto fabrik_rotations = parse_fabrik_rotations(args.fabrik_rotations);
  if (!fabrik_rotations) {
    return report_error("unknown --fabrik-rotations '" + args.fabrik_rotations +
                        "' (expected rest or previous)");
  }

  DrawingOptions options;
  options.solver = *solver;
  options.ik.fabrik_rotations = *fabrik_rotations;
  options.ik.max_iterations = args.max_iterations;
  options.ik.tolerance = args.tolerance;
  options.laps = args.laps;
  options.warm_start = !args.cold_start;
  if (auto error = options.validate()) return report_error(error->message);

  const auto chain = build_chain(lab_arm());
  if (!chain) return report_error(chain.error().message);
  // One target is a one-frame drawing from the rest pose: same solve, same reports.
  std::vector<Vec3> targets;
  IkRunLabel label{args.shape, args.solver};
  if (args.target.empty()) {
    targets = lab_shape_targets(*shape);
  } else {
    Vec3 target;
    if (!parse_vec3(args.target, target)) {
      return report_error("--target must be three finite numbers X,Y,Z, got '" + args.target + "'");
    }
    targets.push_back(target);
    label.shape = "target";
  }
  // Opened before the run, so a missing OpenGL or ffmpeg stops it before any file is written.
  auto pictures = PictureOutput::open(args.pictures, !args.out.empty(), kIkVideoFps);
  if (!pictures) return report_error(pictures.error().message);
  const auto run = run_drawing(*chain, targets, options);
  if (!run) return report_error(run.error().message);
  if (!args.out.empty()) {
    if (auto ok = ensure_output_directory(args.out); !ok) return report_error(ok.error().message);
  }
  if (auto rendered = render_ik_pictures(targets, *run, *pictures, args.out); !rendered) {
    return report_error(rendered.error().message);
  }
  if (!args.out.empty()) {
    if (auto written = write_ik_reports(args.out, label, options, *run); !written) {
      return report_error(written.error().message);
    }
  }
  if (args.target.empty()) {
    print_ik_table_header();
    print_ik_table_row(label.shape, label.solver, summarize(*run));
  } else {
    print_single_target(*chain, *solver, *run);
  }
  if (!args.out.empty()) {
    std::printf("wrote metrics.json, path.csv, drawing.svg%s to %s\n",
                pictures->wants_png() ? ", drawing.png" : "", args.out.c_str());
  }
  if (!args.pictures.video.empty()) std::printf("wrote %s\n", args.pictures.video.c_str());
  return 0;
}

}  // namespace

std::function<int()> add_ik_command(CLI::App& app) {
  auto args = std::make_shared<IkArgs>();
  CLI::App* ik = app.add_subcommand(
      "ik",
      "The lab's arm draws a shape with inverse kinematics, one target per frame "
      "(warm-started from the previous frame), and reports what each solve did.");
  CLI::Option* shape = ik->add_option("--shape", args->shape, "Shape to draw: " + shape_names())
                           ->capture_default_str();
  ik->add_option("--solver", args->solver, "IK solver: ccd or fabrik")->capture_default_str();
  ik->add_option("--max-iterations", args->max_iterations, "Iteration cap per target (>= 1)")
      ->capture_default_str();
  ik->add_option("--tolerance", args->tolerance,
                 "Converged when |end effector - target| <= tolerance (> 0)")
      ->capture_default_str();
  CLI::Option* laps = ik->add_option("--laps", args->laps,
                                     "Times the shape is drawn; the arm resets to rest each lap")
                          ->capture_default_str();
  CLI::Option* cold_start =
      ik->add_flag("--cold-start", args->cold_start,
                   "Solve every target from the rest pose instead of the previous frame's pose");
  ik->add_option("--fabrik-rotations", args->fabrik_rotations,
                 "How FABRIK recovers joint rotations: rest (the lab's, shortest arc from the rest "
                 "bone) or previous (smallest change from the last frame, no twist jumps)")
      ->capture_default_str();
  ik->add_option("--target", args->target,
                 "Solve one target X,Y,Z from the rest pose and print the result, instead of "
                 "drawing a shape (--out then writes its one-frame reports)")
      ->excludes(shape)
      ->excludes(laps)
      ->excludes(cold_start);
  ik->add_option("--out", args->out,
                 "Folder for metrics.json, path.csv, drawing.svg and drawing.png (created if "
                 "needed)");
  add_picture_options(*ik, args->pictures, "drawing.png");
  return [args] { return run(*args); };
}

}  // namespace animkit::cli
