#include "cloth_study_command.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "animkit/cloth/convergence_study.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/material.h"
#include "animkit/core/quote.h"
#include "animkit/io/convergence_report.h"
#include "cli_errors.h"
#include "cloth_command.h"
#include "run_output.h"

namespace animkit::cli {

namespace {

struct ClothStudyArgs {
  std::string scene = "lab";
  int grid = 0;          ///< cells per side; 0: the scene's (lab 10, cotton 100)
  std::string material;  ///< a preset: a physical sheet; empty: the scene's
  int steps = 4;         ///< the default cotton run (every solver) ends in about a minute
  double dt = 1.0 / 60.0;
  double tolerance = 1e-4;
  std::vector<std::string> integrators;  ///< empty: every implicit one
  std::string out;
};

// The scene's grid: the lab's per-particle cloth, or a physical sheet (cotton: 1 m, 101 x 101
// particles; any --material makes the sheet of that material, as `animkit cloth` does).
Result<GridClothOptions> scene_grid(const ClothStudyArgs& args) {
  GridClothOptions grid;
  std::string material = args.material;
  if (args.scene == "cotton") {
    grid.cells = 100;
    grid.size = 1.0;
    if (material.empty()) material = "cotton";
  }
  if (args.grid != 0) grid.cells = args.grid;
  if (!material.empty()) {
    const MaterialPreset* preset = find_material(material);
    if (!preset) {
      return fail("unknown material " + quote_input(material) +
                  " (expected one of: " + material_names() + ")");
    }
    grid.material = preset->material;
    grid.gravity = 9.81;
  }
  if (auto error = grid.validate()) return fail(error->message);
  return grid;
}

std::string title_of(const ClothStudyArgs& args, const GridClothOptions& grid) {
  const std::string what = grid.material
                               ? (args.material.empty() ? std::string("cotton") : args.material)
                               : std::string("the lab's cloth");
  const std::string side = std::to_string(grid.cells + 1);
  char dt[32];
  if (std::abs(1.0 / args.dt - std::round(1.0 / args.dt)) < 1e-9)
    std::snprintf(dt, sizeof dt, "1/%.0f s", 1.0 / args.dt);
  else
    std::snprintf(dt, sizeof dt, "%g s", args.dt);
  return what + ", " + side + " x " + side + " particles, dt " + dt + ": convergence per step";
}

// "implicit-pcg step 3/10" on one rewritten line, only when stderr is a terminal.
StudyProgress progress_line(int steps) {
  if (::isatty(::fileno(stderr)) == 0) return {};
  return [steps](const std::string& integrator, int done) {
    std::fprintf(stderr, "\r%-20s step %d/%d   ", integrator.c_str(), done, steps);
    std::fflush(stderr);
  };
}

int run_cloth_study(const ClothStudyArgs& args) {
  auto grid = scene_grid(args);
  if (!grid) return report_error(grid.error().message);
  ConvergenceStudyOptions options;
  options.dt = args.dt;
  options.steps = args.steps;
  options.tolerance = args.tolerance;
  options.integrators = args.integrators;
  if (auto error = options.validate()) return report_error(error->message);
  auto built = build_cloth(make_grid_cloth(*grid));
  if (!built) return report_error(built.error().message);

  std::string no_video;
  auto output = RunOutput::begin(args.out, no_video);
  if (!output) return report_error(output.error().message);
  const bool tty = ::isatty(::fileno(stderr)) != 0;
  auto study =
      run_convergence_study(built->model, built->state, options, progress_line(args.steps));
  if (tty) std::fprintf(stderr, "\n");
  if (!study) return report_error(study.error().message);

  const std::string scene = args.scene + (args.material.empty() ? "" : " " + args.material) + ", " +
                            std::to_string(grid->cells + 1) + " x " +
                            std::to_string(grid->cells + 1);
  if (auto ok = write_convergence_report(output->dir(), *study, title_of(args, *grid), scene); !ok)
    return report_error(ok.error().message);
  if (auto ok = output->commit(); !ok) return report_error(ok.error().message);
  std::printf("%s", convergence_table_markdown(*study).c_str());
  std::printf("wrote convergence.png, convergence.svg, table.md, curves.csv, study.json to %s\n",
              args.out.c_str());
  return 0;
}

}  // namespace

std::function<int()> add_cloth_study_command(CLI::App& app) {
  auto args = std::make_shared<ClothStudyArgs>();
  CLI::App* study = app.add_subcommand(
      "cloth-study",
      "Runs every implicit cloth integrator from the same state for the same steps and plots "
      "the relative gradient |grad g| / |grad g(y)| against wall time per step "
      "(convergence.png, convergence.svg), with a table of times and iterations.");
  study
      ->add_option("--scene", args->scene,
                   "lab (the lab's 11 x 11 cloth) or cotton (1 m, 101 x 101)")
      ->check(CLI::IsMember({"lab", "cotton"}))
      ->capture_default_str();
  study->add_option("--grid", args->grid, "Cells per side N (default: lab 10, cotton 100)");
  study->add_option("--material", args->material,
                    "A physical sheet of: " + material_names() + " (gravity 9.81)");
  study->add_option("--steps", args->steps, "Steps each solver takes")->capture_default_str();
  study->add_option("--dt", args->dt, "Seconds per step")->capture_default_str();
  study
      ->add_option("--tolerance", args->tolerance,
                   "Every solver stops when the gradient norm is this fraction of its start")
      ->capture_default_str();
  study
      ->add_option(
          "--integrators", args->integrators,
          "Comma-separated, from: " +
              [] {
                std::string names;
                for (const std::string& n : implicit_integrator_names())
                  names += (names.empty() ? "" : ", ") + n;
                return names;
              }() +
              " (default: all of them)")
      ->delimiter(',');
  study->add_option("--out", args->out, "Folder for the plot, table and curves (replaced whole)")
      ->required();
  return [args] { return run_cloth_study(*args); };
}

}  // namespace animkit::cli
