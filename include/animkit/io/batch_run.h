#pragma once
// Running a batch of animkit jobs (batch_jobs.h) on every core: one process each, several at
// once, each into its own results folder OUT/NAME (written whole or not at all, as every animkit
// run), its printed output kept in OUT/logs/NAME.log. A failed job does not stop the others. A
// re-run skips the jobs whose complete results are already there: the same command line, run
// to success, its folder holding every file it listed. The summary OUT/batch.json is rewritten
// after every job, so a batch stopped half way resumes where it was.
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "animkit/core/result.h"
#include "animkit/io/batch_jobs.h"

namespace animkit {

/// How a batch job ended: it ran and exited 0, it failed (non-zero exit, a signal, or it could
/// not start), or it was skipped because an earlier run's complete results were already there.
enum class BatchStatus { ok, failed, skipped };

/// "ok", "failed", "skipped".
std::string_view batch_status_name(BatchStatus status);

/// What became of one batch job: one entry of OUT/batch.json.
struct BatchJobResult {
  std::string name;                      ///< the job's name (BatchJob::name): its folder under OUT
  std::vector<std::string> args;         ///< the job's command line after "animkit", without --out
  BatchStatus status = BatchStatus::ok;  ///< how the job ended
  int exit_code = 0;  ///< the process's (128 + signal when a signal ended it)
  /// Seconds since the batch began when the job started (0 when skipped).
  double started = 0.0, finished = 0.0;  ///< likewise when it ended (0 when skipped)
  /// A failed job's error: its last "animkit: error:" line, else its last line, else why it
  /// could not start.
  std::string error;
  /// Whether the job has ended (or was skipped): the summary lists only these, so a batch
  /// stopped while a job runs does not take that job for done when it resumes.
  bool ended = false;
};

/// How run_batch runs the jobs and where it puts their results.
struct BatchSettings {
  std::filesystem::path program;  ///< the animkit executable the jobs run
  std::filesystem::path out;      ///< the batch's folder (created if needed)
  /// Processes at once (>= 1). Each job runs its loops on one thread when there are several
  /// (OMP_NUM_THREADS=1 unless the environment sets it): the jobs already fill the cores.
  int parallel = 1;
  /// Called as each job ends (or is skipped), with how many have ended of how many.
  std::function<void(const BatchJobResult& result, int ended, int total)> on_job_end;
};

/// Runs the jobs. Errors only for the batch itself (its folder cannot be made or its summary
/// written); a job's failure is in its result.
Result<std::vector<BatchJobResult>> run_batch(std::span<const BatchJob> jobs,
                                              const BatchSettings& settings);

/// OUT/batch.json: {"jobs": [{"name", "args", "status", "exit_code", "seconds", "started",
/// "finished", "error", "folder"}...] (the jobs that have ended), "ok", "failed", "skipped",
/// "wall_seconds", "job_seconds"}.
std::string batch_summary_json(std::span<const BatchJobResult> results,
                               const std::filesystem::path& out);

}  // namespace animkit
