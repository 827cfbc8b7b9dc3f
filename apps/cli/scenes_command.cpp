// `animkit scenes`: every scene of the registry the viewer opens, with the command that runs
// each one here, so the CLI and the viewer name the same scenes; `--write NAME FILE.json`
// writes a built-in cloth scene as a scene file to start one's own from.
#include "scenes_command.h"

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "animkit/core/quote.h"
#include "animkit/io/atomic_write.h"
#include "animkit/io/cloth_scene_writer.h"
#include "animkit/scene/cloth_scenes.h"
#include "animkit/scene/scene_registry.h"
#include "cli_errors.h"

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

// Writes the built-in cloth scene `name` to `path` (whole or not at all).
int write_scene(const std::string& name, const std::string& path) {
  const ClothSceneEntry* entry = find_cloth_scene(name);
  if (!entry) {
    return report_error("unknown cloth scene " + quote_input(name) +
                        " (expected one of: " + cloth_scene_names() + ")");
  }
  auto json = cloth_scene_json(entry->make());
  if (!json) return report_error(json.error().message);
  if (auto ok = write_file_atomic(path, *json); !ok) return report_error(ok.error().message);
  std::printf("wrote %s: the scene %s (animkit cloth --scene %s runs it)\n", path.c_str(),
              name.c_str(), path.c_str());
  return 0;
}

std::function<int()> add_scenes_command(CLI::App& app) {
  CLI::App* scenes = app.add_subcommand(
      "scenes",
      "List the scenes (animkit-viewer --scene NAME opens one; the command beside it runs it "
      "here), or write a built-in cloth scene as a scene file to start one's own from");
  auto write = std::make_shared<std::vector<std::string>>();
  scenes->add_option("--write", *write, "NAME FILE.json: the built-in cloth scene NAME as a file")
      ->expected(2);
  return [write] {
    if (!write->empty()) return write_scene((*write)[0], (*write)[1]);
    for (const SceneEntry& entry : scene_entries()) {
      std::printf("%-16s %-15s %s\n%-16s %-15s   %s\n", std::string(entry.name).c_str(),
                  std::string(scene_kind_title(entry.kind)).c_str(),
                  std::string(entry.summary).c_str(), "", "", cli_command(entry).c_str());
    }
    return 0;
  };
}

}  // namespace animkit::cli
