// `animkit scenes`: every scene of the registry the viewer opens, with the command that runs
// each one here, so the CLI and the viewer name the same scenes.
#include "scenes_command.h"

#include <cstdio>
#include <string>

#include "animkit/scene/scene_registry.h"

namespace animkit::cli {

namespace {

// How the CLI runs the scene `entry` names.
std::string cli_command(const SceneEntry& entry) {
  switch (entry.kind) {
    case SceneKind::ik:
      return "animkit ik";
    case SceneKind::bvh:
      return "animkit footlock --in data/cmu/131_01.bvh --scale 0.056444 --out DIR (or animkit "
             "reach)";
    case SceneKind::cloth:
      return "animkit cloth --scene " + std::string(entry.name);
  }
  return "";
}

}  // namespace

std::function<int()> add_scenes_command(CLI::App& app) {
  app.add_subcommand("scenes",
                     "List the scenes (animkit-viewer --scene NAME opens one; the command "
                     "beside it runs it here)");
  return [] {
    for (const SceneEntry& entry : scene_entries()) {
      std::printf("%-16s %-15s %s\n%-16s %-15s   %s\n", std::string(entry.name).c_str(),
                  std::string(scene_kind_title(entry.kind)).c_str(),
                  std::string(entry.summary).c_str(), "", "", cli_command(entry).c_str());
    }
    return 0;
  };
}

}  // namespace animkit::cli
