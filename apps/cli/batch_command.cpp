#include "batch_command.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>

#include "animkit/io/batch_jobs.h"
#include "animkit/io/batch_run.h"
#include "cli_errors.h"

namespace animkit::cli {

namespace {

struct BatchArgs {
  std::string jobs;
  std::string out = "batch";
  int parallel = 0;  // 0: the machine's cores
};

int run_batch_command(const BatchArgs& args) {
  if (args.parallel < 0 || args.parallel > 1024) {
    return report_error("--jobs must be between 1 and 1024 (0: one per core), got " +
                        std::to_string(args.parallel));
  }
  auto jobs = read_batch_jobs(args.jobs);
  if (!jobs) return report_error(jobs.error().message);
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return report_error("cannot find the animkit program itself: " + error.message());
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  BatchSettings settings{.program = self,
                         .out = args.out,
                         .parallel = args.parallel > 0 ? args.parallel : cores,
                         .on_job_end = {}};
  settings.on_job_end = [](const BatchJobResult& r, int ended, int total) {
    if (r.status == BatchStatus::failed) {
      std::printf("[%d/%d] %s: failed: %s\n", ended, total, r.name.c_str(), r.error.c_str());
    } else if (r.status == BatchStatus::skipped) {
      std::printf("[%d/%d] %s: skipped (complete from an earlier run)\n", ended, total,
                  r.name.c_str());
    } else {
      std::printf("[%d/%d] %s: ok, %.1f s\n", ended, total, r.name.c_str(), r.finished - r.started);
    }
    std::fflush(stdout);
  };
  std::printf("batch: %zu jobs, %d at a time, into %s\n", jobs->size(), settings.parallel,
              args.out.c_str());
  std::fflush(stdout);
  auto results = run_batch(*jobs, settings);
  if (!results) return report_error(results.error().message);

  int failed = 0, skipped = 0;
  double wall = 0.0, serial = 0.0;
  std::size_t width = 4;
  for (const BatchJobResult& r : *results) width = std::max(width, r.name.size());
  std::printf("\n%-*s %-8s %9s  %s\n", static_cast<int>(width), "job", "status", "seconds",
              "error");
  for (const BatchJobResult& r : *results) {
    failed += r.status == BatchStatus::failed ? 1 : 0;
    skipped += r.status == BatchStatus::skipped ? 1 : 0;
    wall = std::max(wall, r.finished);
    serial += r.finished - r.started;
    std::printf("%-*s %-8s %9.2f  %s\n", static_cast<int>(width), r.name.c_str(),
                std::string(batch_status_name(r.status)).c_str(), r.finished - r.started,
                r.error.c_str());
  }
  std::printf("%zu jobs: %zu ok, %d failed, %d skipped; %.1f s of jobs in %.1f s\n",
              results->size(), results->size() - failed - skipped, failed, skipped, serial, wall);
  std::printf("wrote batch.json and logs/ to %s\n", args.out.c_str());
  // Exit 1 (not 2: the batch itself was good) when any job failed.
  return failed > 0 ? 1 : 0;
}

}  // namespace

std::function<int()> add_batch_command(CLI::App& app) {
  auto args = std::make_shared<BatchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "batch",
      "Runs many jobs on all cores, one process each: a JOBS.json list of animkit command lines "
      "(cloth, footlock, reach) or a folder of cloth scene files. Each job writes OUT/NAME; "
      "OUT/batch.json sums them up and OUT/logs/NAME.log keeps what each printed. A failed "
      "job does not stop the others (exit 1 if any failed); a re-run skips the jobs whose "
      "complete results are there.");
  cmd->add_option("jobs", args->jobs, "JOBS.json, or a folder of scene files (*.json)")->required();
  cmd->add_option("--out", args->out, "The batch's folder")->capture_default_str();
  cmd->add_option("--jobs", args->parallel, "Jobs at once (0: one per core)")
      ->capture_default_str();
  return [args] { return run_batch_command(*args); };
}

}  // namespace animkit::cli
