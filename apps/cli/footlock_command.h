#pragma once
#include <CLI/CLI.hpp>
#include <functional>

namespace animkit::cli {

/// Registers `animkit footlock` on `app`; the returned function runs it after parsing.
std::function<int()> add_footlock_command(CLI::App& app);

}  // namespace animkit::cli
