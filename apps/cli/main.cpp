// animkit: command-line front end. Each subcommand is a thin shell over library calls.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "cli_errors.h"
#include "cloth_command.h"
#include "demo_command.h"
#include "ik_command.h"

int main(int argc, char** argv) {
  CLI::App app{
      "animkit: inverse kinematics (CCD, FABRIK) and mass-spring cloth, headless.\n"
      "Run `animkit <command> --help` for a command's options."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "animkit 0.1.0");
  const auto run_ik = animkit::cli::add_ik_command(app);
  const auto run_cloth = animkit::cli::add_cloth_command(app);
  const auto run_demo = animkit::cli::add_demo_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return animkit::cli::report_error(std::string(e.what()) + " (see animkit --help)");
  }
  try {
    if (app.got_subcommand("ik")) return run_ik();
    if (app.got_subcommand("cloth")) return run_cloth();
    return run_demo();
  } catch (const std::exception& e) {  // e.g. out of memory: still one line, never a crash
    return animkit::cli::report_error(e.what());
  }
}
