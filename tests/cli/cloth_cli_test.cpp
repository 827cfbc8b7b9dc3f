// Behaviour tests of `animkit cloth`: the real binary, its output and files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../support/mesh_sheets.h"
#include "../support/run_command.h"
#include "../support/temp_files.h"
#include "animkit/cloth/integrator_registry.h"

namespace cloth_cli_test {

namespace fs = std::filesystem;
using animkit::testing_support::read_file;
using animkit::testing_support::run_command;

const std::string kCli = ANIMKIT_CLI_PATH;

fs::path fresh_dir(const std::string& name) {
  return animkit::testing_support::fresh_dir("cloth_cli_" + name);
}

TEST(ClothCli, WritesMetricsObjAndPointCache) {
  const fs::path out = fresh_dir("lab");
  const auto r = run_command(kCli + " cloth --frames 60 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto m = nlohmann::json::parse(read_file(out / "metrics.json"));
  EXPECT_EQ(m["frames"], 60);
  EXPECT_EQ(m["particles"], 121);
  EXPECT_EQ(m["springs"], 618);
  EXPECT_EQ(m["integrator"], "implicit-pcg");
  EXPECT_EQ(m["diverged"], false);
  EXPECT_GT(m["ms_per_step"]["median"].get<double>(), 0.0);
  EXPECT_GE(m["newton_iterations"]["mean"].get<double>(), 1.0);
  EXPECT_TRUE(m["final_energy"].is_number());
  EXPECT_EQ(m["steps"].size(), 60u);
  EXPECT_EQ(m["converged_fraction"], 1.0);

  const std::string obj = read_file(out / "cloth.obj");
  int vertices = 0, faces = 0;
  for (std::size_t at = obj.find('\n'); at != std::string::npos; at = obj.find('\n', at + 1)) {
    vertices += obj.compare(at + 1, 2, "v ") == 0 ? 1 : 0;
    faces += obj.compare(at + 1, 2, "f ") == 0 ? 1 : 0;
  }
  EXPECT_EQ(vertices, 121);
  EXPECT_EQ(faces, 200);
  const std::string pc2 = read_file(out / "cloth.pc2");
  ASSERT_GE(pc2.size(), 32u);
  EXPECT_EQ(pc2.substr(0, 12), std::string("POINTCACHE2\0", 12));
  std::int32_t samples = 0;
  std::memcpy(&samples, pc2.data() + 28, 4);
  EXPECT_EQ(samples, 61);  // the rest pose and every frame
  EXPECT_EQ(pc2.size(), 32u + 61u * 121u * 12u);
}

TEST(ClothCli, AMaterialGivesAPhysicalSheet) {
  const fs::path out = fresh_dir("cotton");
  const auto r = run_command(kCli +
                             " cloth --material cotton --grid 10 --size 1 --frames 5 --no-picture "
                             "--out " +
                             out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto m = nlohmann::json::parse(read_file(out / "metrics.json"));
  EXPECT_EQ(m["options"]["material"], "cotton");
  EXPECT_EQ(m["options"]["gravity"], 9.81);  // physical gravity unless --gravity says otherwise
  EXPECT_EQ(m["options"]["size"], 1.0);
  // The lab's per-particle mass, stiffness and damping play no part: not reported.
  for (const char* unused : {"mass", "stiffness", "damping"}) {
    EXPECT_FALSE(m["options"].contains(unused)) << unused;
  }
  EXPECT_EQ(m["converged_fraction"], 1.0);
  EXPECT_EQ(m["integrator"], "implicit-multigrid");  // the fast settings, not the lab's CG
  // Axis springs and diagonals plus the coupling springs of the bends; no distance-2 springs.
  EXPECT_EQ(m["springs"], 2 * 10 * 11 + 2 * 10 * 10 + 2 * 9 * 11);
}

TEST(ClothCli, EveryIntegratorRuns) {
  for (const animkit::IntegratorEntry& entry : animkit::cloth_integrators()) {
    const std::string integrator(entry.name);
    const auto r = run_command(kCli + " cloth --grid 4 --frames 10 --integrator " + integrator);
    EXPECT_EQ(r.exit_code, 0) << integrator << ": " << r.err;
    EXPECT_NE(r.out.find(integrator), std::string::npos);
  }
}

TEST(ClothCli, AutoPicksAnIntegratorByTryingThem) {
  const auto r = run_command(kCli + " cloth --grid 6 --frames 5 --integrator auto");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Every implicit integrator was tried, and the run used the one it chose.
  for (const animkit::IntegratorEntry& entry : animkit::cloth_integrators()) {
    if (!animkit::tolerance_of(entry.defaults)) continue;
    EXPECT_NE(r.out.find(std::string(entry.name).append(" ")), std::string::npos) << r.out;
  }
  const std::size_t chose = r.out.find("chose ");
  ASSERT_NE(chose, std::string::npos) << r.out;
  std::string chosen = r.out.substr(chose + 6);
  chosen.resize(chosen.find('\n'));
  EXPECT_NE(animkit::find_integrator(chosen), nullptr) << chosen;
  // The summary row starts with the integrator's name.
  EXPECT_NE(r.out.find(std::string(1, '\n').append(chosen)), std::string::npos) << r.out;
}

TEST(ClothCli, DivergedRunReportsAndWritesNoAnimation) {
  const fs::path out = fresh_dir("diverged");
  const auto r = run_command(kCli +
                             " cloth --integrator explicit --substeps 1 --stiffness 1e4 "
                             "--dt 0.0333 --frames 600 --out " +
                             out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("animkit: error: the simulation diverged in step ", 0), 0u) << r.err;
  // The metrics and the folder's list of outputs, nothing else: no animation, no temporary.
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(out)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{".animkit-outputs", "metrics.json"}));
  EXPECT_EQ(read_file(out / ".animkit-outputs").find(".tmp"), std::string::npos);
  const auto m = nlohmann::json::parse(read_file(out / "metrics.json"));
  EXPECT_EQ(m["diverged"], true);
  EXPECT_EQ(m["divergence"].get<std::string>().rfind("the simulation diverged", 0), 0u);
}

// A 1 m square of 9 x 9 vertices, jittered, as an OBJ file in `dir`.
fs::path square_obj(const fs::path& dir) {
  const fs::path path = dir / "square.obj";
  std::ofstream(path) << animkit::testing_support::obj_text(
      animkit::testing_support::square_sheet(8, 1.0, 1.0, 0.2));
  return path;
}

TEST(ClothCli, AMeshClothWithAMaterialWritesEveryOutput) {
  const fs::path out = fresh_dir("mesh_cotton");
  const fs::path obj = square_obj(fresh_dir("mesh_cotton_in"));
  // Pinned by index (vertex 0: a corner) and by a box around the opposite corner of that edge.
  const auto r = run_command(kCli + " cloth --mesh " + obj.string() +
                             " --material cotton --pin 0 --pin-box -0.01,0.9,0.49,0.01,1.1,0.51 "
                             "--frames 10 --out " +
                             out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto m = nlohmann::json::parse(read_file(out / "metrics.json"));
  EXPECT_EQ(m["particles"], 81);
  EXPECT_EQ(m["converged_fraction"], 1.0);
  EXPECT_EQ(m["options"]["material"], "cotton");
  EXPECT_EQ(m["options"]["gravity"], 9.81);
  EXPECT_TRUE(fs::exists(out / "cloth.obj"));
  EXPECT_TRUE(fs::exists(out / "final.png"));
  const std::string pc2 = read_file(out / "cloth.pc2");
  EXPECT_EQ(pc2.size(), 32u + 11u * 81u * 12u);
  // The pinned vertices 0 and 8 never move: their last frame is their first.
  for (const int v : {0, 8}) {
    EXPECT_EQ(pc2.substr(32 + v * 12, 12), pc2.substr(32 + (10 * 81 + v) * 12, 12)) << v;
  }
}

TEST(ClothCli, AMeshClothWithTheLabsParameters) {
  const fs::path obj = square_obj(fresh_dir("mesh_lab_in"));
  const auto r = run_command(kCli + " cloth --mesh " + obj.string() +
                             " --pin 0,8 --mass 0.5 --stiffness 200 --frames 5 --no-picture");
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

struct BadCloth {
  std::string args;
  std::string message;
};

void PrintTo(const BadCloth& b, std::ostream* os) {
  *os << "animkit cloth " << b.args;
}

class ClothCliBadInput : public testing::TestWithParam<BadCloth> {};

TEST_P(ClothCliBadInput, OneLineOnStderrAndExitCode2) {
  const auto r = run_command(kCli + " cloth " + GetParam().args);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("animkit: error: " + GetParam().message, 0), 0u) << r.err;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ClothCliBadInput,
    testing::Values(
        BadCloth{"--mass -1", "mass must be between 1e-06 and 1e+06, got -1"},
        BadCloth{"--mass nan", "mass must be between 1e-06 and 1e+06, got nan"},
        BadCloth{"--dt 0", "--dt (seconds) must be between 1e-06 and 10, got 0"},
        BadCloth{"--dt -0.1", "--dt (seconds) must be between 1e-06 and 10, got -0.1"},
        BadCloth{"--dt 1e-300", "--dt (seconds) must be between 1e-06 and 10, got 1e-300"},
        BadCloth{"--stiffness 1e300", "stiffness must be between 1e-06 and 1e+09, got 1e+300"},
        BadCloth{"--substeps 2147483647",
                 "substeps must be between 1 and 100000 (or 0 for the default), got 2147483647"},
        BadCloth{"--grid 0", "grid must have between 1 and 500 cells per side, got 0"},
        BadCloth{"--stiffness 0", "stiffness must be between 1e-06 and 1e+09, got 0"},
        BadCloth{"--damping -1", "damping must be between 0 and 1e+06, got -1"},
        BadCloth{"--gravity inf", "gravity must be between -10000 and 10000, got inf"},
        BadCloth{"--frames 0", "--frames must be between 1 and"},
        BadCloth{"--substeps -2", "substeps must be between 1 and 100000"},
        BadCloth{"--tolerance 2", "tolerance must be in (0, 1), got 2"},
        BadCloth{"--material ''", "unknown material ''"},
        BadCloth{"--integrator verlet", "unknown integrator 'verlet'"},
        BadCloth{"--material tweed", "unknown material 'tweed' (expected one of: cotton, silk"},
        BadCloth{"--material COTTON", "unknown material 'COTTON' (expected one of: cotton, silk"},
        BadCloth{"--material cotton --stiffness 10", "--stiffness sets the lab's per-particle"},
        BadCloth{"--material cotton --size nan", "cloth size must be positive and finite, got nan"},
        BadCloth{"--material cotton --size -1", "cloth size must be positive and finite, got -1"},
        BadCloth{"--material cotton --grid 500 --size 0.1",
                 "the material's particle mass at 501 x 501 particles and 0.1 m must be between"},
        BadCloth{"--out /proc/animkit-cannot-write", "cannot create output folder"},
        BadCloth{"--pin 0", "--pin pins vertices of a --mesh; the grid pins the two corners"},
        BadCloth{"--pin-box 0,0,0,1,1,1", "--pin-box pins vertices of a --mesh"},
        BadCloth{"--mesh /nonexistent/cloth.obj", "/nonexistent/cloth.obj: no such file"},
        BadCloth{"--mesh /nonexistent/cloth.obj --grid 4",
                 "--grid shapes the grid; --mesh gives the cloth's shape and size"},
        BadCloth{"--mesh /nonexistent/cloth.obj --pin 1,x",
                 "--pin expects vertex indices I,J,... (counted from 0), got '1,x'"},
        BadCloth{"--mesh /nonexistent/cloth.obj --pin-box 0,0,0,1,1",
                 "--pin-box expects six finite numbers X0,Y0,Z0,X1,Y1,Z1, got '0,0,0,1,1'"}),
    [](const auto& param_info) { return "case" + std::to_string(param_info.index); });

TEST(ClothCli, HelpExplainsEveryOption) {
  const auto r = run_command(kCli + " cloth --help");
  ASSERT_EQ(r.exit_code, 0);
  for (const char* option :
       {"--grid", "--mesh", "--pin", "--pin-box", "--frames", "--dt", "--integrator", "--substeps",
        "--mass", "--stiffness", "--damping", "--gravity", "--tolerance", "--out"}) {
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
  }
}

TEST(ClothCli, AnUnknownOptionPointsAtTheCommandsOwnHelp) {
  const auto r = run_command(kCli + " cloth --frobnicate");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err,
            "animkit: error: The following argument was not expected: --frobnicate (see animkit "
            "cloth --help)\n");
}

}  // namespace cloth_cli_test
