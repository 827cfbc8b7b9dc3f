// Behaviour tests of `animkit ik --limits FILE`: the lab's arm as a one-branch skeleton through
// the tree solvers with joint limits, the same reports as without, and one-line errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "../support/run_command.h"
#include "../support/temp_files.h"

namespace ik_limits_cli_test {

namespace fs = std::filesystem;
using animkit::testing_support::read_file;
using animkit::testing_support::run_command;

const std::string kCli = ANIMKIT_CLI_PATH;
const fs::path kLabArmLimits = ANIMKIT_TEST_DATA_DIR "/limits/lab_arm.json";

fs::path fresh_dir(const std::string& name) {
  return animkit::testing_support::fresh_dir("cli_ik_limits_" + name);
}

fs::path write_limits(const fs::path& dir, const std::string& name, const std::string& json) {
  const fs::path path = dir / name;
  std::ofstream(path) << json;
  return path;
}

// path.csv's rows as numbers (frame, target xyz, end effector xyz, iterations, error, ...).
std::vector<std::vector<double>> csv_rows(const fs::path& path) {
  std::istringstream in(read_file(path));
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) row.push_back(std::stod(field));
    rows.push_back(std::move(row));
  }
  return rows;
}

TEST(IkLimitsCli, EverySolverDrawsTheStarWithTheExampleLimits) {
  for (const char* solver : {"fabrik", "ccd", "dls", "sdls"}) {
    const fs::path out = fresh_dir(std::string("star_") + solver);
    const auto r = run_command(kCli + " ik --shape star --limits " + kLabArmLimits.string() +
                               " --solver " + solver + " --out " + out.string());
    ASSERT_EQ(r.exit_code, 0) << solver << ": " << r.err;
    EXPECT_NE(r.out.find(std::string("star         ") + solver), std::string::npos) << r.out;
    const auto metrics = nlohmann::json::parse(read_file(out / "metrics.json"));
    EXPECT_EQ(metrics["solver"], solver);
    EXPECT_EQ(metrics["limits"], kLabArmLimits.string());
    EXPECT_EQ(metrics["targets"], 400);
    EXPECT_FALSE(metrics["options"].contains("fabrik_rotations"));
    for (const char* key : {"converged_fraction", "unreachable_targets", "iterations", "error",
                            "max_joint_step_rad", "solve_time_us"}) {
      EXPECT_TRUE(metrics.contains(key)) << key;
    }
    EXPECT_EQ(csv_rows(out / "path.csv").size(), 400u);
    EXPECT_TRUE(fs::exists(out / "drawing.svg"));
    // Every solver turns every joint, the root too, and reaches the whole star within these
    // limits (FABRIK through its DLS finish); CCD and DLS without jitter.
    EXPECT_EQ(metrics["converged_fraction"], 1.0) << solver;
    if (std::string(solver) == "ccd" || std::string(solver) == "dls") {
      EXPECT_LT(metrics["max_joint_step_rad"].get<double>(), 0.01) << solver;
    }
  }
}

// Hinges about z at every joint keep the arm in the plane z = 0 whatever the target: the
// limits act inside the solver, and the star's targets off that plane are missed.
TEST(IkLimitsCli, HingesAboutZKeepTheArmInItsPlane) {
  const fs::path dir = fresh_dir("planar");
  std::string json = "{";
  for (int j = 0; j < 4; ++j) {
    json += std::string(j ? "," : "") + "\"joint" + std::to_string(j) +
            "\": {\"type\": \"hinge\", \"axis\": [0, 0, 1], \"min\": -170, \"max\": 170}";
  }
  const fs::path limits = write_limits(dir, "planar.json", json + "}");
  for (const char* solver : {"fabrik", "ccd", "dls", "sdls"}) {
    const fs::path out = dir / solver;
    const auto r = run_command(kCli + " ik --shape star --limits " + limits.string() +
                               " --solver " + solver + " --out " + out.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    double largest_z = 0.0, largest_target_z = 0.0;
    for (const auto& row : csv_rows(out / "path.csv")) {
      largest_z = std::max(largest_z, std::abs(row[6]));
      largest_target_z = std::max(largest_target_z, std::abs(row[3]));
    }
    EXPECT_LT(largest_z, 1e-9) << solver;
    EXPECT_GT(largest_target_z, 0.1);
    EXPECT_LT(nlohmann::json::parse(read_file(out / "metrics.json"))["converged_fraction"], 0.5)
        << solver;
  }
}

// A limits file that leaves every joint free: tree CCD on the one-branch skeleton turns the
// joints as the chain's CCD does, so the drawn path is the lab's to rounding.
TEST(IkLimitsCli, FreeLimitsDrawThePathOfTheChainSolver) {
  const fs::path dir = fresh_dir("free");
  const fs::path limits = write_limits(dir, "free.json", R"({"joint1": {"type": "free"}})");
  auto r = run_command(kCli + " ik --shape star --solver ccd --out " + (dir / "chain").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_command(kCli + " ik --shape star --solver ccd --limits " + limits.string() + " --out " +
                  (dir / "tree").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto chain = csv_rows(dir / "chain" / "path.csv");
  const auto tree = csv_rows(dir / "tree" / "path.csv");
  ASSERT_EQ(chain.size(), tree.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    for (int c = 4; c <= 6; ++c) largest = std::max(largest, std::abs(chain[i][c] - tree[i][c]));
  }
  EXPECT_LT(largest, 1e-9);
}

TEST(IkLimitsCli, SingleTargetWithLimitsPrintsTheTreeSolversResult) {
  const auto r =
      run_command(kCli + " ik --target 0.3,0,0.2 --solver sdls --limits " + kLabArmLimits.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("solver       sdls"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("joint 4"), std::string::npos) << r.out;
}

TEST(IkLimitsCli, BadLimitsAndSolversAreOneLineErrors) {
  const fs::path dir = fresh_dir("errors");
  const std::string lab = " --limits " + kLabArmLimits.string();
  const std::string typo =
      write_limits(dir, "typo.json", R"({"joint9": {"type": "free"}})").string();
  const std::string broken = write_limits(dir, "broken.json", "{\"joint1\": ").string();
  const std::string bad_hinge =
      write_limits(dir, "hinge.json",
                   R"({"joint1": {"type": "hinge", "axis": [0, 0, 1], "min": 10, "max": -10}})")
          .string();
  const std::pair<std::string, std::string> cases[] = {
      {"ik --shape star --solver jacobian" + lab,
       "unknown solver 'jacobian' (expected fabrik, ccd, dls or sdls with --limits)"},
      {"ik --shape star --limits " + (dir / "missing.json").string(), "missing.json"},
      {"ik --shape star --limits " + typo, "joint9"},
      {"ik --shape star --limits " + broken, "broken.json"},
      {"ik --shape star --limits " + bad_hinge, "hinge.json"},
      {"ik --shape star --fabrik-rotations previous" + lab, "--fabrik-rotations excludes --limits"},
  };
  for (const auto& [args, message] : cases) {
    const auto r = run_command(kCli + " " + args + " --out " + (dir / "o").string());
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(fs::exists(dir / "o")) << args;
  }
}

}  // namespace ik_limits_cli_test
