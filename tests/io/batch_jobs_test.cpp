// The jobs of `animkit batch`: a JSON list read whole and checked before anything runs, or a
// folder of scene files. (The runs themselves: tests/cli/batch_cli_test.cpp.)
#include "animkit/io/batch_jobs.h"

#include <gtest/gtest.h>

#include <fstream>

#include "../support/temp_files.h"
#include "animkit/io/batch_run.h"

namespace animkit {
namespace {

TEST(BatchJobs, AListOfCommandLines) {
  const auto jobs = parse_batch_jobs(
      R"({"jobs": [{"name": "drape.v2", "args": ["cloth", "--scene", "drape-sphere"]},
                   {"name": "walk_1", "args": ["footlock", "--in", "a b.bvh"]}]})",
      "jobs.json");
  ASSERT_TRUE(jobs) << jobs.error().message;
  ASSERT_EQ(jobs->size(), 2u);
  EXPECT_EQ((*jobs)[0].name, "drape.v2");
  EXPECT_EQ((*jobs)[1].args, (std::vector<std::string>{"footlock", "--in", "a b.bvh"}));
}

TEST(BatchJobs, BadListsSayWhatIsWrong) {
  const struct {
    const char* text;
    const char* message;
  } cases[] = {
      {"[]", "j.json: expected an object with a \"jobs\" array"},
      {R"({"job": []})", "j.json: jobs: missing (the list of jobs)"},
      {R"({"jobs": [3]})", "j.json: jobs[0]: expected an object"},
      {R"({"jobs": [{"args": ["cloth"]}]})", "j.json: jobs[0].name: missing"},
      {R"({"jobs": [{"name": "a"}]})", "j.json: jobs[0].args: missing"},
      {R"({"jobs": [{"name": "a", "args": []}]})", "j.json: jobs[0].args: is empty"},
      {R"({"jobs": [{"name": "a", "args": ["cloth", 3]}]})",
       "j.json: jobs[0].args: expected strings"},
      {R"({"jobs": [{"name": "a", "args": ["cloth", "--out=x"]}]})",
       "j.json: jobs[0].args: has --out: the batch gives each job its folder"},
      {R"({"jobs": [{"name": "logs", "args": ["cloth"]}]})",
       "j.json: jobs[0].name: 'logs' is the batch's own (its logs/ folder and batch.json)"},
      {R"({"jobs": [{"name": "batch.json", "args": ["cloth"]}]})",
       "j.json: jobs[0].name: 'batch.json' is the batch's own"},
      {R"({"jobs": [{"name": ".hidden", "args": ["cloth"]}]})",
       "j.json: jobs[0].name: '.hidden' starts with '.'"},
      {R"({"jobs": [{"name": "a", "args": ["cloth"]}, {"name": "a", "args": ["reach"]}]})",
       "j.json: two jobs are named 'a'"},
      {R"({"jobs": [{"name": "a", "args": ["cloth"]}], "jobs": []})",
       "j.json: the key 'jobs' appears twice in one object"},
  };
  for (const auto& c : cases) {
    const auto jobs = parse_batch_jobs(c.text, "j.json");
    ASSERT_FALSE(jobs) << c.text;
    EXPECT_EQ(jobs.error().message.rfind(c.message, 0), 0u) << jobs.error().message;
  }
}

TEST(BatchJobs, AFolderOfSceneFilesIsOneClothJobEach) {
  const auto dir = testing_support::fresh_dir("batch_scenes");
  std::ofstream(dir / "b.json") << "{}";
  std::ofstream(dir / "a.json") << "{}";
  std::ofstream(dir / "notes.txt") << "not a scene";
  const auto jobs = read_batch_jobs(dir);
  ASSERT_TRUE(jobs) << jobs.error().message;
  ASSERT_EQ(jobs->size(), 2u);
  EXPECT_EQ((*jobs)[0].name, "a");
  EXPECT_EQ((*jobs)[0].args,
            (std::vector<std::string>{"cloth", "--scene", (dir / "a.json").string()}));
  std::ofstream(dir / "bad name.json") << "{}";
  EXPECT_EQ(read_batch_jobs(dir).error().message,
            (dir / "bad name.json").string() +
                ": the file's name may hold only letters, digits, '.', '_' and '-' (it names "
                "the job)");
  EXPECT_FALSE(read_batch_jobs(dir / "missing.json"));
}

TEST(BatchSummary, ListsOnlyTheJobsThatEnded) {
  // A batch stopped while "b" runs: its summary must not say "b" is done, or a resumed batch
  // would skip it.
  std::vector<BatchJobResult> results(2);
  results[0] = {.name = "a",
                .args = {"cloth"},
                .status = BatchStatus::ok,
                .exit_code = 0,
                .started = 0.0,
                .finished = 1.0,
                .error = "",
                .ended = true};
  results[1] = {.name = "b",
                .args = {"cloth"},
                .status = BatchStatus::ok,
                .exit_code = 0,
                .started = 0.5,
                .finished = 0.0,
                .error = "",
                .ended = false};
  const std::string json = batch_summary_json(results, "out");
  EXPECT_NE(json.find("\"name\": \"a\""), std::string::npos) << json;
  EXPECT_EQ(json.find("\"name\": \"b\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"ok\": 1"), std::string::npos) << json;
}

}  // namespace
}  // namespace animkit
