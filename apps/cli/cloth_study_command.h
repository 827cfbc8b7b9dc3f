#pragma once
// `animkit cloth-study`: the convergence study of the implicit integrators.
#include <CLI/CLI.hpp>
#include <functional>

namespace animkit::cli {

/// Registers `animkit cloth-study` on `app`; the returned function runs it after parsing.
std::function<int()> add_cloth_study_command(CLI::App& app);

}  // namespace animkit::cli
