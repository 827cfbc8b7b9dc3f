// Behaviour tests of `animkit ik` and `animkit demo`: the real binary, its output and files.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "../support/run_command.h"
#include "../support/temp_files.h"

namespace ik_cli_test {

namespace fs = std::filesystem;
using animkit::testing_support::run_command;

const std::string kCli = ANIMKIT_CLI_PATH;

fs::path fresh_dir(const std::string& name) {
  return animkit::testing_support::fresh_dir("cli_" + name);
}
using animkit::testing_support::read_file;

int count_lines(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

TEST(IkCli, WritesMetricsPathAndDrawing) {
  const fs::path out = fresh_dir("star_fabrik");
  const auto r = run_command(kCli + " ik --shape star --solver fabrik --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("star"), std::string::npos);
  const auto metrics = nlohmann::json::parse(read_file(out / "metrics.json"));
  EXPECT_EQ(metrics["solver"], "fabrik");
  EXPECT_EQ(metrics["shape"], "star");
  EXPECT_EQ(metrics["targets"], 400);
  EXPECT_EQ(metrics["converged_fraction"], 1.0);
  EXPECT_EQ(metrics["unreachable_targets"], 0);
  for (const char* key : {"iterations", "error", "max_joint_step_rad", "solve_time_us"}) {
    EXPECT_TRUE(metrics.contains(key)) << key;
  }
  EXPECT_EQ(count_lines(read_file(out / "path.csv")), 401);  // header + one row per frame
  const std::string svg = read_file(out / "drawing.svg");
  EXPECT_NE(svg.find("star"), std::string::npos);
  EXPECT_NE(svg.find("fabrik"), std::string::npos);
}

TEST(IkCli, LapsMultiplyTheFrames) {
  const fs::path out = fresh_dir("laps");
  const auto r = run_command(kCli + " ik --shape square --laps 2 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(read_file(out / "metrics.json"))["targets"], 300);
}

TEST(IkCli, SingleTargetPrintsTheResult) {
  const auto r = run_command(kCli + " ik --solver ccd --target 0.5,0,0.3");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("converged    yes"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("reachable    yes"), std::string::npos);
}

TEST(IkCli, SingleTargetWritesOneFrameReports) {
  const fs::path out = fresh_dir("single");
  const auto r = run_command(kCli + " ik --solver fabrik --target 0.5,0,0.3 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto metrics = nlohmann::json::parse(read_file(out / "metrics.json"));
  EXPECT_EQ(metrics["targets"], 1);
  EXPECT_EQ(metrics["shape"], "target");
  EXPECT_EQ(count_lines(read_file(out / "path.csv")), 2);
}

TEST(IkCli, UnreachableTargetIsReported) {
  const auto r = run_command(kCli + " ik --solver fabrik --target 3,0,0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("reachable    no"), std::string::npos) << r.out;
}

struct BadInvocation {
  std::string args;
  std::string message;  // expected start of the stderr line after "animkit: error: "
};

void PrintTo(const BadInvocation& b, std::ostream* os) {
  *os << "animkit " << b.args;
}

class IkCliBadInput : public testing::TestWithParam<BadInvocation> {};

TEST_P(IkCliBadInput, OneLineOnStderrAndExitCode2) {
  const auto r = run_command(kCli + " " + GetParam().args);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("animkit: error: " + GetParam().message, 0), 0u) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, IkCliBadInput,
    testing::Values(
        BadInvocation{"ik --shape hexagon", "unknown shape 'hexagon'"},
        BadInvocation{"ik --solver jacobian", "unknown solver 'jacobian'"},
        BadInvocation{"ik --fabrik-rotations twist", "unknown --fabrik-rotations 'twist'"},
        BadInvocation{"ik --tolerance 0", "tolerance must be a positive finite number"},
        BadInvocation{"ik --tolerance -1", "tolerance must be a positive finite number"},
        BadInvocation{"ik --tolerance abc", "Could not convert"},
        BadInvocation{"ik --max-iterations 0", "max iterations must be at least 1"},
        BadInvocation{"ik --laps 0", "laps must be at least 1"},
        BadInvocation{"ik --laps 2000000000", "2000000000 laps of 150 targets make"},
        BadInvocation{"ik --target 1,0,0 --shape star", "--shape excludes --target"},
        BadInvocation{"ik --target 1,2",
                      "--target must be three numbers X,Y,Z each within +-1e+09, got '1,2'"},
        BadInvocation{"ik --target nan,0,0", "--target must be three numbers"},
        BadInvocation{"ik --target 1e160,0,0",
                      "--target must be three numbers X,Y,Z each within +-1e+09, got '1e160,0,0'"},
        BadInvocation{"ik --shape circle --box 0,0,1",
                      "--box applies to --text, --image, --mnist and --curve"},
        BadInvocation{"ik --picture-frame -1",
                      "--picture-frame must be a frame number from 0, got -1"},
        BadInvocation{"ik --target 1,2,3,4", "--target must be three numbers"},
        BadInvocation{"ik --out /proc/animkit-cannot-write", "cannot create output folder"},
        BadInvocation{"ik --no-such-option", "The following argument"},
        BadInvocation{"", "A subcommand is required"}),
    [](const auto& param_info) { return "case" + std::to_string(param_info.index); });

TEST(IkCli, UnwritableOutputWritesNothing) {
  const fs::path dir = fresh_dir("blocked");
  std::ofstream(dir / "file") << "x";
  const auto r = run_command(kCli + " ik --out " + (dir / "file").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(read_file(dir / "file"), "x");
}

TEST(IkCli, HelpExplainsEveryOption) {
  const auto r = run_command(kCli + " ik --help");
  ASSERT_EQ(r.exit_code, 0);
  for (const char* option : {"--shape", "--solver", "--max-iterations", "--tolerance", "--laps",
                             "--target", "--out", "--cold-start", "--fabrik-rotations"}) {
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
  }
  const auto top = run_command(kCli + " --help");
  ASSERT_EQ(top.exit_code, 0);
  EXPECT_NE(top.out.find("ik"), std::string::npos);
  EXPECT_NE(top.out.find("demo"), std::string::npos);
}

TEST(DemoCli, DrawsEveryShapeWithBothSolvers) {
  const fs::path out = fresh_dir("demo");
  const auto r = run_command(kCli + " demo --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* shape : {"circle", "square", "heart", "triangle", "star"}) {
    for (const char* solver : {"ccd", "fabrik"}) {
      const fs::path dir = out / "ik" / (std::string(shape) + "-" + solver);
      const auto metrics = nlohmann::json::parse(read_file(dir / "metrics.json"));
      EXPECT_EQ(metrics["converged_fraction"], 1.0) << dir;
      EXPECT_TRUE(fs::exists(dir / "drawing.svg"));
      EXPECT_TRUE(fs::exists(dir / "drawing.png"));
    }
  }
  // Then the custom drawings: initials, and the uneven spiral before and after resampling.
  for (const char* custom : {"text-QD-ccd", "spiral-ccd", "spiral-even-ccd"}) {
    const auto metrics = nlohmann::json::parse(read_file(out / "ik" / custom / "metrics.json"));
    EXPECT_EQ(metrics["converged_fraction"], 1.0) << custom;
    EXPECT_TRUE(metrics.contains("drawing")) << custom;
  }
  EXPECT_EQ(count_lines(read_file(out / "ik" / "summary.csv")), 14);
  for (const char* name : {"metrics.json", "cloth.obj", "cloth.pc2", "final.png"}) {
    EXPECT_TRUE(fs::exists(out / "cloth" / name)) << name;
  }
}

}  // namespace ik_cli_test
