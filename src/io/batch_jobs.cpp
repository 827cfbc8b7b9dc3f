#include "animkit/io/batch_jobs.h"

#include <algorithm>
#include <set>

#include "animkit/io/file_bytes.h"
#include "held_fp_exceptions.h"
#include "json_fields.h"

namespace animkit {

namespace {

constexpr std::uintmax_t kMaxJobsFileBytes = 64u << 20;
constexpr std::size_t kMaxJobNameLength = 100;

std::optional<std::string> job_name_problem(const std::string& name) {
  if (name.empty()) return "is empty";
  if (name == "logs" || name == "batch.json") {
    return "is the batch's own (its logs/ folder and batch.json)";
  }
  if (name.size() > kMaxJobNameLength) return "is longer than 100 characters";
  if (name.front() == '.') return "starts with '.'";
  for (char c : name) {
    const bool allowed = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                         (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-';
    if (!allowed) return "may hold only letters, digits, '.', '_' and '-'";
  }
  return std::nullopt;
}

std::string command_names() {
  std::string names;
  for (std::string_view c : kBatchCommands) names += (names.empty() ? "" : ", ") + std::string(c);
  return names;
}

BatchJob read_job(const nlohmann::json& value, const std::string& path) {
  if (!value.is_object()) throw FieldError(path + ": expected an object");
  JsonFields fields(value, path);
  BatchJob job;
  job.name = fields.string("name").value_or("");
  if (!fields.has("name")) fields.error("name", "missing (the job's results folder)");
  if (auto problem = job_name_problem(job.name)) {
    fields.error("name", "'" + job.name + "' " + *problem);
  }
  const nlohmann::json* args = fields.array("args");
  if (args == nullptr)
    fields.error("args", "missing (the animkit command line, e.g. [\"cloth\", ...])");
  for (const nlohmann::json& arg : *args) {
    if (!arg.is_string()) fields.error("args", "expected strings");
    job.args.push_back(arg.get<std::string>());
  }
  if (job.args.empty()) fields.error("args", "is empty");
  if (std::find(kBatchCommands.begin(), kBatchCommands.end(), job.args.front()) ==
      kBatchCommands.end()) {
    fields.error("args", "unknown command '" + job.args.front() + "' (expected one of " +
                             command_names() + ")");
  }
  for (const std::string& arg : job.args) {
    if (arg == "--out" || arg.starts_with("--out=")) {
      fields.error("args", "has --out: the batch gives each job its folder");
    }
  }
  fields.finish();
  return job;
}

std::optional<std::string> repeated_name(const std::vector<BatchJob>& jobs) {
  std::set<std::string> seen;
  for (const BatchJob& job : jobs) {
    if (!seen.insert(job.name).second) return job.name;
  }
  return std::nullopt;
}

}  // namespace

Result<std::vector<BatchJob>> parse_batch_jobs(std::string_view text, std::string_view name) {
  const std::string prefix = std::string(name) + ": ";
  const HeldFloatingPointExceptions held;
  auto parsed = parse_json_document(text, prefix);
  if (!parsed) return fail(parsed.error().message);
  std::vector<BatchJob> jobs;
  try {
    if (!parsed->is_object()) throw FieldError("expected an object with a \"jobs\" array");
    JsonFields document(*parsed, "");
    const nlohmann::json* list = document.array("jobs");
    if (list == nullptr) throw FieldError("jobs: missing (the list of jobs)");
    if (list->empty()) throw FieldError("jobs: is empty");
    if (list->size() > kMaxBatchJobs) {
      throw FieldError("jobs: more than " + std::to_string(kMaxBatchJobs) + " jobs");
    }
    for (std::size_t i = 0; i < list->size(); ++i) {
      jobs.push_back(read_job((*list)[i], element_path("jobs", i)));
    }
    document.finish();
  } catch (const FieldError& e) {
    return fail(prefix + e.what());
  }
  if (auto name_twice = repeated_name(jobs)) {
    return fail(prefix + "two jobs are named '" + *name_twice + "'");
  }
  return jobs;
}

Result<std::vector<BatchJob>> read_batch_jobs(const std::filesystem::path& source) {
  std::error_code error;
  if (!std::filesystem::is_directory(source, error)) {
    auto bytes = read_file_bytes(source, kMaxJobsFileBytes);
    if (!bytes) return fail(bytes.error().message);
    return parse_batch_jobs(*bytes, source.string());
  }
  std::vector<std::filesystem::path> scenes;
  for (std::filesystem::directory_iterator it(source, error), end; !error && it != end;
       it.increment(error)) {
    if (it->path().extension() == ".json") scenes.push_back(it->path());
  }
  if (error) return fail(source.string() + ": cannot list the folder: " + error.message());
  std::sort(scenes.begin(), scenes.end());
  if (scenes.empty()) return fail(source.string() + ": no scene files (*.json) in the folder");
  std::vector<BatchJob> jobs;
  for (const auto& scene : scenes) {
    BatchJob job{.name = scene.stem().string(),
                 .args = {"cloth", "--scene", std::filesystem::absolute(scene).string()}};
    if (auto problem = job_name_problem(job.name)) {
      return fail(scene.string() + ": the file's name " + *problem + " (it names the job)");
    }
    jobs.push_back(std::move(job));
  }
  return jobs;
}

}  // namespace animkit
