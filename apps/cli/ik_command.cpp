#include "ik_command.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "animkit/core/quote.h"
#include "animkit/core/validation.h"
#include "animkit/io/atomic_write.h"
#include "animkit/io/drawing_source.h"
#include "animkit/io/ik_report.h"
#include "animkit/io/joint_limits_file.h"
#include "animkit/kinematics/chain.h"
#include "animkit/kinematics/drawing_session.h"
#include "animkit/kinematics/skeleton_drawing_session.h"
#include "cli_errors.h"
#include "drawing_args.h"
#include "ik_pictures.h"
#include "ik_table.h"
#include "run_output.h"

namespace animkit::cli {

namespace {

struct IkArgs {
  apps::DrawingArgs drawing;
  std::string solver = "ccd";
  int max_iterations = IkOptions{}.max_iterations;
  double tolerance = IkOptions{}.tolerance;
  int laps = 1;
  bool cold_start = false;
  std::string fabrik_rotations = "rest";
  std::string target;
  std::string limits;  ///< a joint limits file: the arm runs as a skeleton through the tree solvers
  std::string out;
  PictureArgs pictures;
  std::optional<int> picture_frame;
};

// "text QD: 4 strokes, 1234 targets (56 with the pen up), spacing 0.0100 (cv 0.012), before
// resampling 0.0132 (cv 0.61)"
void print_drawing(const PreparedDrawing& d, int pen_up) {
  std::printf("drawing: %s: %d stroke%s, %zu targets (%d with the pen up), spacing %.4g (cv %.3f)",
              d.name.c_str(), d.strokes, d.strokes == 1 ? "" : "s", d.trajectory.targets.size(),
              pen_up, d.spacing_after.mean, d.spacing_after.cv);
  if (d.spacing_before.segments != d.spacing_after.segments) {
    std::printf(", before resampling %.4g (cv %.3f)", d.spacing_before.mean, d.spacing_before.cv);
  }
  std::printf("\n");
}

void print_single_target(std::string_view solver, const DrawingRun& run) {
  const DrawingFrame& frame = run.frames.front();
  const IkResult& result = frame.ik;
  std::printf("solver       %s\n", std::string(solver).c_str());
  std::printf("target       %s\n", to_string(frame.target).c_str());
  std::printf("end effector %s\n", to_string(frame.end_effector).c_str());
  std::printf("iterations   %d\n", result.iterations);
  std::printf("error        %.3e\n", result.error);
  std::printf("converged    %s\n", result.converged ? "yes" : "no");
  std::printf("reachable    %s%s\n", result.reachable ? "yes" : "no",
              result.reachable ? "" : " (the arm points straight at the target)");
  for (std::size_t i = 0; i < run.final_pose.global_positions.size(); ++i) {
    std::printf("joint %zu      %s\n", i, to_string(run.final_pose.global_positions[i]).c_str());
  }
}

// With --limits: the lab's arm as a one-branch skeleton (joints joint0..joint4), its limits
// from the file, and the tree solver named by --solver.
struct LimitedArm {
  Skeleton skeleton;
  std::vector<JointLimit> limits;
  TreeIkSolverKind solver;
};

Result<LimitedArm> limited_arm(const IkArgs& args) {
  const auto solver = parse_tree_ik_solver(args.solver);
  if (!solver) {
    return fail("unknown solver " + quote_input(args.solver) +
                " (expected fabrik, ccd, dls or sdls with --limits)");
  }
  auto skeleton = build_skeleton(skeleton_desc_from_chain(lab_arm()));
  if (!skeleton) return fail(skeleton.error().message);
  const auto set = read_joint_limits_file(args.limits);
  if (!set) return fail(set.error().message);
  auto limits = bind_joint_limits(*set, skeleton->names());
  if (!limits) {
    return fail(args.limits + ": " + limits.error().message +
                " (the lab arm's joints are joint0 to joint" +
                std::to_string(skeleton->joint_count() - 1) + ")");
  }
  return LimitedArm{std::move(*skeleton), std::move(*limits), *solver};
}

int run(const IkArgs& args) {
  std::optional<LimitedArm> arm;
  std::optional<IkSolverKind> solver = IkSolverKind::ccd;
  if (!args.limits.empty()) {
    auto limited = limited_arm(args);
    if (!limited) return report_error(limited.error().message);
    arm = std::move(*limited);
  } else {
    solver = parse_ik_solver(args.solver);
    if (!solver) {
      return report_error("unknown solver " + quote_input(args.solver) +
                          " (expected ccd or fabrik)");
    }
  }

  const auto fabrik_rotations = parse_fabrik_rotations(args.fabrik_rotations);
  if (!fabrik_rotations) {
    return report_error("unknown --fabrik-rotations " + quote_input(args.fabrik_rotations) +
                        " (expected rest or previous)");
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
  Trajectory trajectory;
  IkRunLabel label{"target", args.solver, std::nullopt};
  if (arm) label.limits = args.limits;
  std::optional<PreparedDrawing> drawing;
  if (args.target.empty()) {
    const auto request = apps::drawing_request(args.drawing);
    if (!request) return report_error(request.error().message);
    auto prepared = prepare_drawing(request->first, request->second, *chain);
    if (!prepared) return report_error(prepared.error().message);
    drawing = std::move(*prepared);
    trajectory = drawing->trajectory;
    label.shape = drawing->name;
    label.drawing = DrawingStats{
        drawing->strokes,
        static_cast<int>(std::count(trajectory.pen_down.begin(), trajectory.pen_down.end(), 0)),
        drawing->spacing_before, drawing->spacing_after};
  } else {
    const apps::DrawingArgs& d = args.drawing;
    if (d.text || !d.image.empty() || !d.mnist.empty() || !d.curve.empty()) {
      return report_error("--target excludes --text, --image, --mnist and --curve");
    }
    if (d.spacing || !d.box.empty() || d.threshold || d.thinning) {
      return report_error(
          "--target is one point: --spacing, --box, --threshold and --thinning "
          "do not apply");
    }
    Vec3 target;
    if (!parse_vec3(args.target, target) || target.cwiseAbs().maxCoeff() > kMaxTargetCoordinate) {
      return report_error("--target must be three numbers X,Y,Z each within +-" +
                          format_number(kMaxTargetCoordinate) + ", got " +
                          quote_input(args.target));
    }
    trajectory = Trajectory::all_pen_down({target});
  }
  if (args.picture_frame && *args.picture_frame < 0) {
    return report_error("--picture-frame must be a frame number from 0, got " +
                        std::to_string(*args.picture_frame));
  }
  // The --out folder is filled through a staging folder and swapped in whole at the end.
  std::string video = args.pictures.video;
  auto output = RunOutput::begin(args.out, video);
  if (!output) return report_error(output.error().message);
  // Opened before the run, so a missing OpenGL or ffmpeg stops it before any file is written.
  PictureArgs picture_args = args.pictures;
  picture_args.video = video;
  auto pictures = PictureOutput::open(picture_args, output->has_folder(), kIkVideoFps);
  if (!pictures) return report_error(pictures.error().message);
  const auto run =
      arm ? run_skeleton_drawing(
                arm->skeleton, arm->skeleton.joint_count() - 1, arm->limits, trajectory.targets,
                SkeletonDrawingOptions{arm->solver, options.ik.max_iterations, options.ik.tolerance,
                                       options.laps, options.warm_start},
                trajectory.pen_down)
          : run_drawing(*chain, trajectory.targets, options, trajectory.pen_down);
  if (!run) return report_error(run.error().message);
  if (args.picture_frame && *args.picture_frame >= static_cast<int>(run->frames.size())) {
    return report_error("--picture-frame " + std::to_string(*args.picture_frame) +
                        " is past the last frame (" + std::to_string(run->frames.size() - 1) + ")");
  }
  if (auto rendered =
          render_ik_pictures(trajectory, *run, *pictures, output->dir(), args.picture_frame);
      !rendered) {
    return report_error(rendered.error().message);
  }
  if (output->has_folder()) {
    if (auto written = write_ik_reports(output->dir(), label, options, *run); !written) {
      return report_error(written.error().message);
    }
  }
  if (auto ok = output->commit(); !ok) return report_error(ok.error().message);
  if (drawing) {
    const DrawingSummary summary = summarize(*run);
    print_ik_table_header();
    print_ik_table_row(label.shape, label.solver, summary);
    print_drawing(*drawing, label.drawing->pen_up_targets);
    if (summary.unreachable_targets > 0) {
      std::printf("warning: %d targets are out of the arm's reach (see path.csv)\n",
                  summary.unreachable_targets);
    }
  } else {
    print_single_target(arm ? to_string(arm->solver) : to_string(*solver), *run);
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
  CLI::Option* shape = apps::add_drawing_options(*ik, args->drawing);
  ik->add_option("--solver", args->solver,
                 "IK solver: ccd or fabrik (the lab's chain solvers); with --limits a tree solver: "
                 "fabrik, ccd, dls or sdls")
      ->capture_default_str();
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
  CLI::Option* fabrik_rotations =
      ik->add_option(
            "--fabrik-rotations", args->fabrik_rotations,
            "How FABRIK recovers joint rotations: rest (the lab's, shortest arc from the rest "
            "bone) or previous (smallest change from the last frame, no twist jumps)")
          ->capture_default_str();
  ik->add_option("--limits", args->limits,
                 "Joint limits JSON (joint0..joint4, degrees; e.g. data/limits/lab_arm.json): the "
                 "arm runs as a one-branch skeleton through the tree solvers with these limits")
      ->excludes(fabrik_rotations);
  ik->add_option("--target", args->target,
                 "Solve one target X,Y,Z from the rest pose and print the result, instead of "
                 "drawing a shape (--out then writes its one-frame reports)")
      ->excludes(shape)
      ->excludes(laps)
      ->excludes(cold_start);
  ik->add_option("--out", args->out,
                 "Folder for metrics.json, path.csv, drawing.svg and drawing.png (created if "
                 "needed; replaced whole when the run ends, see docs/errors.md)");
  add_picture_options(*ik, args->pictures, "drawing.png");
  ik->add_option("--picture-frame", args->picture_frame,
                 "Show frame N (from 0) in drawing.png instead of the last: the arm mid-drawing");
  return [args] { return run(*args); };
}

}  // namespace animkit::cli
