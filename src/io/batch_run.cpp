#include "animkit/io/batch_run.h"

#include <sys/wait.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "animkit/io/atomic_write.h"
#include "animkit/io/file_bytes.h"
#include "animkit/io/staged_folder.h"
#include "child_process.h"
#include "held_fp_exceptions.h"

namespace animkit {

namespace {

namespace fs = std::filesystem;

constexpr const char* kSummaryName = "batch.json";

// A job's results are whole when its folder lists its files (StagedFolder::commit) and each
// of them is there.
bool folder_is_complete(const fs::path& folder) {
  std::ifstream list(folder / kOutputListName);
  if (!list) return false;
  std::string line;
  std::error_code error;
  while (std::getline(list, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!fs::exists(folder / line, error)) return false;
  }
  return true;
}

// The earlier summary's jobs that ended well: name -> their command line.
std::map<std::string, std::vector<std::string>> earlier_successes(const fs::path& out) {
  std::map<std::string, std::vector<std::string>> done;
  auto bytes = read_file_bytes(out / kSummaryName, 256u << 20);
  if (!bytes) return done;
  const HeldFloatingPointExceptions held;  // a damaged summary's huge number is not a crash
  const auto summary = nlohmann::json::parse(*bytes, nullptr, /*allow_exceptions=*/false);
  if (!summary.is_object() || !summary.contains("jobs") || !summary["jobs"].is_array()) return done;
  for (const auto& job : summary["jobs"]) {
    if (!job.is_object() || !job.contains("name") || !job.contains("args") ||
        !job.contains("status") || !job["name"].is_string() || !job["args"].is_array()) {
      continue;
    }
    if (job["status"] != "ok" && job["status"] != "skipped") continue;
    std::vector<std::string> args;
    for (const auto& arg : job["args"])
      if (arg.is_string()) args.push_back(arg.get<std::string>());
    done[job["name"].get<std::string>()] = std::move(args);
  }
  return done;
}

// The line that says why a job failed.
std::string failure_line(const std::string& output) {
  std::string last, error;
  std::size_t begin = 0;
  while (begin < output.size()) {
    std::size_t end = output.find('\n', begin);
    if (end == std::string::npos) end = output.size();
    std::string line = output.substr(begin, end - begin);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") != std::string::npos) last = line;
    if (line.starts_with("animkit: error: ")) error = line;
    begin = end + 1;
  }
  return !error.empty() ? error : last;
}

struct Running {
  std::size_t index;
  detail::PipeCollector output;
};

}  // namespace

std::string_view batch_status_name(BatchStatus status) {
  switch (status) {
    case BatchStatus::ok:
      return "ok";
    case BatchStatus::failed:
      return "failed";
    case BatchStatus::skipped:
      return "skipped";
  }
  return "?";
}

Result<std::vector<BatchJobResult>> run_batch(std::span<const BatchJob> jobs,
                                              const BatchSettings& settings) {
  if (settings.parallel < 1) return fail("a batch runs at least one job at a time");
  if (auto ok = ensure_output_directory(settings.out); !ok) return fail(ok.error().message);
  if (auto ok = ensure_output_directory(settings.out / "logs"); !ok)
    return fail(ok.error().message);
  if (settings.parallel > 1) ::setenv("OMP_NUM_THREADS", "1", /*overwrite=*/0);
  const auto earlier = earlier_successes(settings.out);
  const auto begin = std::chrono::steady_clock::now();
  const auto now = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  };

  std::vector<BatchJobResult> results(jobs.size());
  std::map<pid_t, Running> running;
  std::size_t next = 0;
  int ended = 0;
  const auto end_job = [&](std::size_t i) -> Result<void> {
    ++ended;
    results[i].ended = true;
    if (settings.on_job_end) settings.on_job_end(results[i], ended, static_cast<int>(jobs.size()));
    return write_file_atomic(settings.out / kSummaryName,
                             batch_summary_json(results, settings.out));
  };
  while (next < jobs.size() || !running.empty()) {
    while (next < jobs.size() && running.size() < static_cast<std::size_t>(settings.parallel)) {
      const std::size_t i = next++;
      const BatchJob& job = jobs[i];
      BatchJobResult& r = results[i];
      r.name = job.name;
      r.args = job.args;
      const fs::path folder = settings.out / job.name;
      const auto done = earlier.find(job.name);
      if (done != earlier.end() && done->second == job.args && folder_is_complete(folder)) {
        r.status = BatchStatus::skipped;
        if (auto ok = end_job(i); !ok) return fail(ok.error().message);
        continue;
      }
      std::vector<std::string> argv = {settings.program.string()};
      argv.insert(argv.end(), job.args.begin(), job.args.end());
      argv.push_back("--out");
      argv.push_back(folder.string());
      auto output = detail::PipeCollector::open();
      r.started = now();
      auto pid = output ? detail::spawn_program(argv, -1, output->child_end(), output->child_end())
                        : Result<pid_t>(fail(output.error().message));
      if (!pid) {
        r.status = BatchStatus::failed;
        r.exit_code = 127;
        r.error = pid.error().message;
        r.finished = r.started;
        if (auto ok = end_job(i); !ok) return fail(ok.error().message);
        continue;
      }
      output->start();
      running.emplace(*pid, Running{i, std::move(*output)});
    }
    if (running.empty()) continue;
    // Only the batch's own children are waited for (another child of the process keeps its
    // exit status for whoever started it): each is asked in turn, without blocking.
    int status = 0;
    auto it = running.end();
    while (it == running.end()) {
      for (auto candidate = running.begin(); candidate != running.end(); ++candidate) {
        const pid_t done = ::waitpid(candidate->first, &status, WNOHANG);
        if (done == candidate->first) {
          it = candidate;
          break;
        }
        if (done < 0 && errno != EINTR) {
          return fail(std::string("waiting for the batch's jobs failed: ") + std::strerror(errno));
        }
      }
      if (it == running.end()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    const std::size_t i = it->second.index;
    const std::string output = it->second.output.finish();
    running.erase(it);
    BatchJobResult& r = results[i];
    r.finished = now();
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.status = r.exit_code == 0 ? BatchStatus::ok : BatchStatus::failed;
    if (r.status == BatchStatus::failed) {
      r.error = failure_line(output);
      if (r.error.empty()) r.error = "exited with code " + std::to_string(r.exit_code);
    }
    if (auto ok = write_file_atomic(settings.out / "logs" / (r.name + ".log"), output); !ok)
      return fail(ok.error().message);
    if (auto ok = end_job(i); !ok) return fail(ok.error().message);
  }
  return results;
}

std::string batch_summary_json(std::span<const BatchJobResult> results, const fs::path& out) {
  nlohmann::ordered_json jobs = nlohmann::ordered_json::array();
  int counts[3] = {0, 0, 0};
  double wall = 0.0, job_seconds = 0.0;
  for (const BatchJobResult& r : results) {
    if (!r.ended) continue;  // not ended yet: not listed as if it had
    counts[static_cast<int>(r.status)] += 1;
    wall = std::max(wall, r.finished);
    job_seconds += r.finished - r.started;
    jobs.push_back({{"name", r.name},
                    {"args", r.args},
                    {"status", batch_status_name(r.status)},
                    {"exit_code", r.exit_code},
                    {"seconds", r.finished - r.started},
                    {"started", r.started},
                    {"finished", r.finished},
                    {"error", r.error},
                    {"folder", (out / r.name).string()}});
  }
  const nlohmann::ordered_json summary = {{"jobs", jobs},         {"ok", counts[0]},
                                          {"failed", counts[1]},  {"skipped", counts[2]},
                                          {"wall_seconds", wall}, {"job_seconds", job_seconds}};
  return summary.dump(1) + "\n";
}

}  // namespace animkit
