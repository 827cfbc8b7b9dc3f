// Behaviour tests of `animkit batch`: jobs run two at a time into their own folders, a broken
// job is reported without stopping the others, a re-run skips complete results, a folder of
// scene files is a batch, and a bad jobs file is one line and exit 2. Its speed on two cores is
// measured by farm-bench, not here (docs/gltf-and-batches.md has the numbers).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../support/run_command.h"
#include "../support/temp_files.h"

namespace batch_cli_test {

namespace fs = std::filesystem;
using animkit::testing_support::read_file;
using animkit::testing_support::run_command;

const std::string kCli = ANIMKIT_CLI_PATH;

fs::path fresh_dir(const std::string& name) {
  return animkit::testing_support::fresh_dir("cli_batch_" + name);
}

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

// Seven cloth jobs (the lab's cloth, stiffnesses 60 to 180) and one with an unknown option.
std::string eight_jobs() {
  nlohmann::json jobs = nlohmann::json::array();
  for (int k = 0; k < 7; ++k) {
    jobs.push_back({{"name", "lab-" + std::to_string(k)},
                    {"args",
                     {"cloth", "--frames", "120", "--stiffness", std::to_string(60 + 20 * k),
                      "--no-picture"}}});
  }
  jobs.push_back({{"name", "broken"}, {"args", {"cloth", "--frames", "120", "--stiffnes", "1"}}});
  return nlohmann::json{{"jobs", jobs}}.dump(1);
}

nlohmann::json summary(const fs::path& out) {
  return nlohmann::json::parse(read_file(out / "batch.json"));
}

TEST(BatchCli, RunsJobsTwoAtATimeAndReportsTheBrokenOne) {
  const fs::path dir = fresh_dir("eight");
  write(dir / "jobs.json", eight_jobs());
  const auto r = run_command(kCli + " batch " + (dir / "jobs.json").string() + " --jobs 2 --out " +
                             (dir / "runs").string());
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("8 jobs: 7 ok, 1 failed, 0 skipped"), std::string::npos) << r.out;
  const nlohmann::json s = summary(dir / "runs");
  ASSERT_EQ(s["jobs"].size(), 8u);
  EXPECT_EQ(s["ok"], 7);
  EXPECT_EQ(s["failed"], 1);
  for (const auto& job : s["jobs"]) {
    const std::string name = job["name"];
    if (name == "broken") {
      EXPECT_EQ(job["status"], "failed");
      EXPECT_EQ(job["exit_code"], 2);
      EXPECT_EQ(job["error"].get<std::string>().rfind("animkit: error: ", 0), 0u) << job["error"];
      EXPECT_FALSE(fs::exists(dir / "runs" / name));
    } else {
      EXPECT_EQ(job["status"], "ok") << name;
      EXPECT_TRUE(fs::exists(dir / "runs" / name / "cloth.pc2")) << name;
      EXPECT_TRUE(fs::exists(dir / "runs" / name / "cloth.glb")) << name;
    }
    EXPECT_TRUE(fs::exists(dir / "runs" / "logs" / (name + ".log"))) << name;
  }
  // Two at a time: the first two jobs start together, before either ends.
  const auto& a = s["jobs"][0];
  const auto& b = s["jobs"][1];
  EXPECT_LT(b["started"].get<double>(), a["finished"].get<double>());
  EXPECT_LT(a["started"].get<double>(), b["finished"].get<double>());
}

TEST(BatchCli, ARerunSkipsCompleteResultsAndRedoesTheRest) {
  const fs::path dir = fresh_dir("rerun");
  write(dir / "jobs.json", eight_jobs());
  const std::string command =
      kCli + " batch " + (dir / "jobs.json").string() + " --out " + (dir / "runs").string();
  ASSERT_EQ(run_command(command).exit_code, 1);
  // One job's results lost, another's command changed: those two run again.
  fs::remove_all(dir / "runs" / "lab-3" / "cloth.pc2");
  std::string jobs = eight_jobs();
  jobs.replace(jobs.find("\"60\""), 4, "\"65\"");
  write(dir / "jobs.json", jobs);
  const auto r = run_command(command);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("8 jobs: 2 ok, 1 failed, 5 skipped"), std::string::npos) << r.out;
  const nlohmann::json s = summary(dir / "runs");
  EXPECT_EQ(s["jobs"][0]["status"], "ok");  // lab-0, its stiffness changed
  EXPECT_EQ(s["jobs"][3]["status"], "ok");  // lab-3, its point cache gone
  EXPECT_EQ(s["jobs"][1]["status"], "skipped");
}

TEST(BatchCli, AFolderOfSceneFilesIsABatch) {
  const fs::path dir = fresh_dir("scenes");
  fs::create_directories(dir / "scenes");
  write(dir / "scenes" / "small.json", R"({"cloth": {"grid": 4}, "frames": 3})");
  write(dir / "scenes" / "smaller.json", R"({"cloth": {"grid": 3}, "frames": 2})");
  const auto r = run_command(kCli + " batch " + (dir / "scenes").string() + " --out " +
                             (dir / "runs").string());
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(fs::exists(dir / "runs" / "small" / "metrics.json"));
  EXPECT_TRUE(fs::exists(dir / "runs" / "smaller" / "metrics.json"));
}

TEST(BatchCli, BadJobsAreOneLineAndExit2) {
  const fs::path dir = fresh_dir("bad");
  const struct {
    const char* jobs;
    const char* message;
  } cases[] = {
      {R"({"jobs": [{"name": "a", "args": ["ik"]}]})",
       "jobs[0].args: unknown command 'ik' (expected one of cloth, footlock, reach)"},
      {R"({"jobs": [{"name": "a", "args": ["cloth", "--out", "x"]}]})",
       "jobs[0].args: has --out: the batch gives each job its folder"},
      {R"({"jobs": [{"name": "a", "args": ["cloth"]}, {"name": "a", "args": ["cloth"]}]})",
       "two jobs are named 'a'"},
      {R"({"jobs": [{"name": "a/b", "args": ["cloth"]}]})",
       "jobs[0].name: 'a/b' may hold only letters, digits, '.', '_' and '-'"},
      {R"({"jobs": [{"name": "..", "args": ["cloth"]}]})", "jobs[0].name: '..' starts with '.'"},
      {R"({"jobs": []})", "jobs: is empty"},
      {R"({"jobs": [{"name": "a", "args": ["cloth"], "frames": 3}]})", "jobs[0]: unknown key"},
  };
  for (const auto& c : cases) {
    write(dir / "jobs.json", c.jobs);
    const auto r = run_command(kCli + " batch " + (dir / "jobs.json").string() + " --out " +
                               (dir / "runs").string());
    EXPECT_EQ(r.exit_code, 2) << c.jobs;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir / "runs")) << c.jobs;
  }
  fs::create_directories(dir / "empty");
  const auto r = run_command(kCli + " batch " + (dir / "empty").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no scene files (*.json) in the folder"), std::string::npos) << r.err;
}

}  // namespace batch_cli_test
