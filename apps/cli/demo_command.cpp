#include "demo_command.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "animkit/io/atomic_write.h"
#include "animkit/io/drawing_source.h"
#include "animkit/io/ik_report.h"
#include "animkit/kinematics/chain.h"
#include "animkit/kinematics/drawing_session.h"
#include "animkit/trajectory/lab_shapes.h"
#include "cli_errors.h"
#include "cloth_command.h"
#include "ik_pictures.h"
#include "ik_table.h"
#include "run_output.h"

namespace animkit::cli {

namespace {

struct DemoArgs {
  std::string out = "out/demo";
  bool no_picture = false;
};

// Draws one trajectory into dir, writes its reports and picture, prints its row and adds it to
// the summary; 0 or the exit code of the error it reported.
int draw_into(const Chain& chain, const std::filesystem::path& dir, const IkRunLabel& label,
              const Trajectory& trajectory, const DrawingOptions& options, PictureOutput& pictures,
              std::string& csv) {
  const auto run = run_drawing(chain, trajectory.targets, options, trajectory.pen_down);
  if (!run) return report_error(run.error().message);
  if (auto ok = ensure_output_directory(dir); !ok) return report_error(ok.error().message);
  if (auto ok = render_ik_pictures(trajectory, *run, pictures, dir); !ok) {
    return report_error(ok.error().message);
  }
  if (auto ok = write_ik_reports(dir, label, options, *run); !ok) {
    return report_error(ok.error().message);
  }
  const DrawingSummary s = summarize(*run);
  print_ik_table_row(label.shape, label.solver, s);
  char row[256];
  std::snprintf(row, sizeof row, "%s,%s,%d,%.6f,%d,%.4f,%d,%.6e,%.6f,%.4f\n", label.shape.c_str(),
                label.solver.c_str(), s.targets, s.converged_fraction, s.unreachable_targets,
                s.iterations_mean, s.iterations_max, s.error_max, s.max_joint_step_rad,
                s.solve_time_us_median);
  csv += row;
  return 0;
}

// Every lab shape with every solver, lab defaults, then custom drawings (initials, the uneven
// spiral as sampled and evened out) with CCD; one folder of reports per drawing and a
// summary.csv comparing them.
int run_ik_shapes(const DemoArgs& args, const std::filesystem::path& out) {
  const auto chain = build_chain(lab_arm());
  if (!chain) return report_error(chain.error().message);
  const std::filesystem::path ik_dir = out / "ik";
  if (auto ok = ensure_output_directory(ik_dir); !ok) return report_error(ok.error().message);

  std::printf(
      "The lab's arm draws its five shapes with both solvers (lab defaults: %d "
      "iterations, tolerance %g, warm start), then custom drawings.\n\n",
      IkOptions{}.max_iterations, IkOptions{}.tolerance);
  PictureArgs picture_args;
  picture_args.no_picture = args.no_picture;
  auto pictures = PictureOutput::open(picture_args, true, kIkVideoFps);
  if (!pictures) return report_error(pictures.error().message);
  print_ik_table_header();
  std::string csv =
      "shape,solver,targets,converged_fraction,unreachable_targets,iterations_mean,"
      "iterations_max,error_max,max_joint_step_rad,solve_time_us_median\n";
  for (LabShape shape : all_lab_shapes()) {
    for (IkSolverKind solver : all_ik_solvers()) {
      DrawingOptions options;
      options.solver = solver;
      const IkRunLabel label{std::string(to_string(shape)), std::string(to_string(solver)),
                             std::nullopt};
      const int code =
          draw_into(*chain, ik_dir / (label.shape + "-" + label.solver), label,
                    Trajectory::all_pen_down(lab_shape_targets(shape)), options, *pictures, csv);
      if (code != 0) return code;
    }
  }
  struct Custom {
    const char* folder;
    DrawingSource source;
    DrawingLayout layout;
  };
  DrawingSource text;
  text.kind = DrawingSourceKind::text;
  text.text = "QD";
  DrawingSource spiral;
  spiral.shape = "spiral";
  const Custom customs[] = {{"text-QD-ccd", text, {}},
                            {"spiral-ccd", spiral, {}},
                            {"spiral-even-ccd", spiral, {.spacing = 0.01}}};
  for (const Custom& custom : customs) {
    auto drawing = prepare_drawing(custom.source, custom.layout, *chain);
    if (!drawing) return report_error(drawing.error().message);
    const Trajectory& t = drawing->trajectory;
    const IkRunLabel label{
        drawing->name + (custom.layout.spacing ? " even" : ""), "ccd",
        DrawingStats{drawing->strokes,
                     static_cast<int>(std::count(t.pen_down.begin(), t.pen_down.end(), 0)),
                     drawing->spacing_before, drawing->spacing_after}};
    const int code = draw_into(*chain, ik_dir / custom.folder, label, t, {}, *pictures, csv);
    if (code != 0) return code;
  }
  if (auto ok = write_file_atomic(ik_dir / "summary.csv", csv); !ok) {
    return report_error(ok.error().message);
  }
  const std::filesystem::path shown = std::filesystem::path(args.out) / "ik";
  std::printf("\nOutputs: %s/<drawing>-<solver>/{metrics.json,path.csv,drawing.svg%s} and %s\n",
              shown.string().c_str(), args.no_picture ? "" : ",drawing.png",
              (shown / "summary.csv").string().c_str());
  return 0;
}

int run(const DemoArgs& args) {
  // Everything goes into a staging folder swapped in at the end: the demo folder holds the
  // previous complete demo or this one.
  std::string no_video;
  auto output = RunOutput::begin(args.out, no_video);
  if (!output) return report_error(output.error().message);
  // The IK part's renderer (and its OpenGL context) is gone before the cloth makes its own.
  if (const int code = run_ik_shapes(args, output->dir()); code != 0) return code;

  std::printf("\nThe lab's cloth (11 x 11, lab parameters) for 5 s at 60 steps per second:\n\n");
  ClothArgs cloth;
  cloth.out = (std::filesystem::path(args.out) / "cloth").string();  // as printed
  cloth.pictures.no_picture = args.no_picture;
  return run_cloth_in(cloth, output->dir() / "cloth", no_video, [&] { return output->commit(); });
}

}  // namespace

std::function<int()> add_demo_command(CLI::App& app) {
  auto args = std::make_shared<DemoArgs>();
  CLI::App* demo = app.add_subcommand(
      "demo",
      "Runs the built-in default scenes (the lab's arm drawing every shape with CCD and "
      "FABRIK, and the lab's cloth), prints summary tables and writes every output to a "
      "folder.");
  demo->add_option("--out", args->out,
                   "Output folder (created if needed; replaced whole when the run ends)")
      ->capture_default_str();
  demo->add_flag("--no-picture", args->no_picture,
                 "Write no PNG pictures (drawing.png, final.png): no OpenGL needed");
  return [args] { return run(*args); };
}

}  // namespace animkit::cli
