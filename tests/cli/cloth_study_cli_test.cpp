// Behaviour tests of `animkit cloth-study`: the real binary, its table and its files.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "../support/run_command.h"
#include "../support/temp_files.h"
#include "animkit/cloth/convergence_study.h"
#include "animkit/io/png.h"

namespace cloth_study_cli_test {

namespace fs = std::filesystem;
using animkit::testing_support::read_file;
using animkit::testing_support::run_command;

const std::string kCli = ANIMKIT_CLI_PATH;

fs::path fresh_dir(const std::string& name) {
  return animkit::testing_support::fresh_dir("cloth_study_cli_" + name);
}

TEST(ClothStudyCli, WritesPlotTableAndCurvesForEveryImplicitSolver) {
  const fs::path out = fresh_dir("lab");
  const auto r = run_command(kCli + " cloth-study --grid 4 --steps 3 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> names = animkit::implicit_integrator_names();
  EXPECT_NE(r.out.find("| solver | median ms/step |"), std::string::npos) << r.out;
  for (const std::string& name : names)
    EXPECT_NE(r.out.find("| " + name + " |"), std::string::npos);
  EXPECT_EQ(read_file(out / "table.md") +
                "wrote convergence.png, convergence.svg, table.md, "
                "curves.csv, study.json to " +
                out.string() + "\n",
            r.out);

  const auto png = animkit::read_image(out / "convergence.png");
  ASSERT_TRUE(png.has_value()) << png.error().message;
  EXPECT_GE(png->width, 320);
  const std::string svg = read_file(out / "convergence.svg");
  EXPECT_NE(svg.find("<svg "), std::string::npos);
  EXPECT_NE(svg.find("the lab&apos;s cloth, 5 x 5 particles, dt 1/60 s"), std::string::npos);
  const auto j = nlohmann::json::parse(read_file(out / "study.json"));
  ASSERT_EQ(j["solvers"].size(), names.size());
  for (const auto& solver : j["solvers"]) {
    EXPECT_EQ(solver["steps"].size(), 3u);
    EXPECT_EQ(solver["steps"][0]["curve"][0], nlohmann::json::array({0.0, 1.0}));
  }
  EXPECT_EQ(j["tolerance"], 1e-4);
  EXPECT_EQ(read_file(out / "curves.csv").rfind("solver,step,iteration,ms,relative_gradient\n", 0),
            0u);
}

TEST(ClothStudyCli, ChosenSolversOnAPhysicalSheet) {
  const fs::path out = fresh_dir("cotton");
  const auto r = run_command(kCli +
                             " cloth-study --scene cotton --grid 8 --steps 2 --tolerance 1e-3 "
                             "--integrators vbd,implicit-pcg --out " +
                             out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(read_file(out / "study.json"));
  ASSERT_EQ(j["solvers"].size(), 2u);
  EXPECT_EQ(j["solvers"][0]["integrator"], "vbd");
  EXPECT_EQ(j["solvers"][1]["integrator"], "implicit-pcg");
  EXPECT_EQ(j["tolerance"], 1e-3);
  EXPECT_NE(read_file(out / "convergence.svg").find("cotton, 9 x 9 particles"), std::string::npos);
}

TEST(ClothStudyCli, BadArgumentsGetOneLineAndNoFiles) {
  const fs::path out = fresh_dir("bad");
  const struct {
    std::string args, message;
  } cases[] = {
      {"--integrators implicit-pcg,verlet", "unknown integrator 'verlet' (expected one of: "},
      {"--integrators explicit", "integrator 'explicit' does not iterate to a tolerance"},
      {"--steps 0", "steps must be between 1 and 10000, got 0"},
      {"--tolerance 2", "tolerance must be between 0 and 1 (exclusive), got 2"},
      {"--material felt", "unknown material 'felt' (expected one of: cotton"},
      {"--scene moon", "--scene"},
  };
  for (const auto& c : cases) {
    const auto r =
        run_command(kCli + " cloth-study " + c.args + " --out " + (out / "run").string());
    EXPECT_EQ(r.exit_code, 2) << c.args;
    EXPECT_EQ(r.err.rfind("animkit: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(fs::exists(out / "run")) << c.args;
  }
  const auto no_out = run_command(kCli + " cloth-study --steps 1");
  EXPECT_EQ(no_out.exit_code, 2);
  EXPECT_NE(no_out.err.find("--out"), std::string::npos) << no_out.err;
}

}  // namespace cloth_study_cli_test
