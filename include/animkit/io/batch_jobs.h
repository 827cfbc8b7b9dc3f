#pragma once
// The jobs of `animkit batch`: a JSON list of animkit command lines, or a folder of cloth scene
// files (each one job). Read whole and checked before any job runs.
//
//   {"jobs": [{"name": "drape-fine", "args": ["cloth", "--scene", "drape-sphere", "--grid", "60"]},
//             {"name": "walk", "args": ["footlock", "--in", "data/cmu/131_01.bvh",
//                                       "--scale", "0.056444"]}]}
//
// Paths inside args are the command's own: relative ones are taken from the folder animkit
// batch runs in.
#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "animkit/core/result.h"

namespace animkit {

/// One job of a batch: an animkit command line and the name of its results folder.
struct BatchJob {
  /// The job's results folder under the batch's output folder: letters, digits, '.', '_' and
  /// '-' (not starting with '.'), at most 100 characters, unique in the batch.
  std::string name;
  /// The command line after "animkit": a command of kBatchCommands and its options, without
  /// --out (the batch gives each job its folder).
  std::vector<std::string> args;
};

/// The commands a batch runs: those that write a results folder.
inline constexpr std::array<std::string_view, 3> kBatchCommands = {"cloth", "footlock", "reach"};

/// Most jobs in one batch.
inline constexpr std::size_t kMaxBatchJobs = 100'000;

/// The jobs in JOBS.json text; `name` starts every error ("jobs.json: jobs[2].name: ..."):
/// not JSON, no "jobs" array, a job without a name or args, a bad or repeated name, an unknown
/// command, --out among the args, unknown keys.
Result<std::vector<BatchJob>> parse_batch_jobs(std::string_view text, std::string_view name);

/// A JOBS.json file, or a folder: then every *.json in it (sorted by name) is a cloth scene
/// file run as `cloth --scene FILE`, named after the file. Errors name the path.
Result<std::vector<BatchJob>> read_batch_jobs(const std::filesystem::path& source);

}  // namespace animkit
