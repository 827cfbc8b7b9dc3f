#pragma once
#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/integrator_registry.h"
#include "mesh_cloth_args.h"
#include "picture_output.h"
#include "world_args.h"

namespace animkit::cli {

/// Everything `animkit cloth` is asked to do.
struct ClothArgs {
  GridClothOptions grid;  ///< the lab's cloth by default
  MeshClothArgs mesh;     ///< --mesh: a cloth cut from an OBJ mesh instead of the grid
  WorldArgs world;        ///< colliders, ground and wind
  /// The grid-only options given on the command line (--grid, --size): refused with --mesh.
  std::vector<std::string> grid_options_given;
  int frames = 300;
  double dt = 1.0 / 60.0;
  std::string integrator{integrator_entry(SimulationOptions{}.integrator).name};
  int substeps = 0;
  double tolerance = NewtonSettings{}.tolerance;
  /// A material preset (material.h); empty: the lab's per-particle parameters.
  std::string material;
  bool material_given = false;  ///< --material was on the command line (even empty: an error)
  bool gravity_given = false;   ///< --gravity was on the command line (else 9.81 with a material)
  /// The lab-parameter options given on the command line (--mass, ...): a material sets them.
  std::vector<std::string> lab_options_given;
  /// --scene: a built-in scene's name or a JSON scene file; empty: the options' own world.
  std::string scene;
  /// Every option given on the command line ("--frames"), for what a --scene lets replace.
  std::vector<std::string> options_given;
  /// The options given that describe the cloth or its world (refused with --scene).
  std::vector<std::string> world_options_given;
  bool given(std::string_view option) const {
    return std::find(options_given.begin(), options_given.end(), option) != options_given.end();
  }
  std::string out;  ///< empty: write no files
  bool no_gltf = false;  ///< --no-gltf: no cloth.glb in the --out folder
  PictureArgs pictures;
};

/// Runs the simulation, prints the summary table, writes the files into the --out folder
/// (replaced whole at the end, see RunOutput); returns the exit code.
int run_cloth(const ClothArgs& args);

/// The same run writing into `out` (no files when empty) and the video to `video` (none when
/// empty); `commit` is called once every file of the run is written (also after a divergence,
/// whose metrics are the run's result), before the error or the summary is printed.
int run_cloth_in(const ClothArgs& args, const std::filesystem::path& out, const std::string& video,
                 const std::function<Result<void>()>& commit);

/// "cotton, silk, ...": the --material choices, for help and messages.
std::string material_names();

/// Registers `animkit cloth` on `app`; the returned function runs it after parsing.
std::function<int()> add_cloth_command(CLI::App& app);

}  // namespace animkit::cli
