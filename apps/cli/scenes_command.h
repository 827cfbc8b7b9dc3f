#pragma once
#include <CLI/CLI.hpp>
#include <functional>

namespace animkit::cli {

/// Registers `animkit scenes` on `app`: lists the scene registry (scene_registry.h), the same
/// list the viewer's --scene and menu show. The returned function runs it after parsing.
std::function<int()> add_scenes_command(CLI::App& app);

}  // namespace animkit::cli
