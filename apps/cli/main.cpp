// animkit: command-line front end. Each subcommand is a thin shell over library calls.
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "animkit/io/temporary_files.h"
#include "batch_command.h"
#include "cli_errors.h"
#include "cloth_command.h"
#include "cloth_study_command.h"
#include "demo_command.h"
#include "footlock_command.h"
#include "ik_command.h"
#include "reach_command.h"
#include "scenes_command.h"

namespace {

// The printed results are part of the run: a full or closed standard output is an error, not
// a success with the result lost (`animkit ik --target 1,0,0 >/dev/full`).
int check_standard_output(int code) {
  if (std::fflush(stdout) == 0 && !std::ferror(stdout)) return code;
  const int error = errno;
  if (code != 0) return code;  // already reported
  return animkit::cli::report_error(std::string("cannot write the results to standard output: ") +
                                    std::strerror(error != 0 ? error : EIO));
}

int run(CLI::App& app, int argc, char** argv) {
  app.description(
      "animkit: inverse kinematics (CCD, FABRIK), foot locking and hand reaching of BVH "
      "characters, mass-spring cloth, "
      "headless.\n"
      "Run `animkit <command> --help` for a command's options.");
  app.require_subcommand(1);
  app.set_version_flag("--version", "animkit 0.1.0");
  const auto run_ik = animkit::cli::add_ik_command(app);
  const auto run_cloth = animkit::cli::add_cloth_command(app);
  const auto run_cloth_study = animkit::cli::add_cloth_study_command(app);
  const auto run_demo = animkit::cli::add_demo_command(app);
  const auto run_footlock = animkit::cli::add_footlock_command(app);
  const auto run_reach = animkit::cli::add_reach_command(app);
  const auto run_scenes = animkit::cli::add_scenes_command(app);
  const auto run_batch = animkit::cli::add_batch_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // The subcommand whose options were wrong has the help that explains them.
    std::string help = "animkit --help";
    for (const CLI::App* sub : app.get_subcommands([](CLI::App* a) { return a->parsed(); })) {
      help = "animkit " + sub->get_name() + " --help";
    }
    return animkit::cli::report_error(std::string(e.what()) + " (see " + help + ")");
  }
  try {
    if (app.got_subcommand("ik")) return run_ik();
    if (app.got_subcommand("cloth")) return run_cloth();
    if (app.got_subcommand("cloth-study")) return run_cloth_study();
    if (app.got_subcommand("footlock")) return run_footlock();
    if (app.got_subcommand("reach")) return run_reach();
    if (app.got_subcommand("scenes")) return run_scenes();
    if (app.got_subcommand("batch")) return run_batch();
    return run_demo();
  } catch (const std::bad_alloc&) {  // one line that says what ran out, never a crash
    return animkit::cli::report_error(
        "out of memory: the run needed more than this machine (or its memory limit) could give");
  } catch (const std::exception& e) {  // still one line, never a crash
    return animkit::cli::report_error(e.what());
  }
}

}  // namespace

int main(int argc, char** argv) {
  // First, before any thread exists: SIGINT, SIGTERM and SIGHUP then remove the run's
  // temporary files and staging folder and stop ffmpeg before the process ends.
  animkit::install_signal_cleanup();
  CLI::App app;
  return check_standard_output(run(app, argc, argv));
}
