#pragma once
#include <CLI/CLI.hpp>
#include <functional>

namespace animkit::cli {

/// Registers `animkit batch` on `app`: runs a list of jobs (batch_jobs.h) on all cores, each
/// into its own folder, resumable (batch_run.h). The returned function runs it after parsing.
std::function<int()> add_batch_command(CLI::App& app);

}  // namespace animkit::cli
