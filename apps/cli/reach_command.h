#pragma once
#include <CLI/CLI.hpp>
#include <functional>

namespace animkit::cli {

/// Registers `animkit reach` on `app`; the returned function runs it after parsing.
std::function<int()> add_reach_command(CLI::App& app);

}  // namespace animkit::cli
