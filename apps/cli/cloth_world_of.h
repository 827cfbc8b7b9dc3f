#pragma once
// What `animkit cloth` simulates, as one ClothWorldDesc: a --scene (built-in or JSON file),
// or the sheet, colliders and air its options describe.
#include "animkit/cloth/cloth_world.h"
#include "animkit/io/cloth_report.h"
#include "cloth_command.h"

namespace animkit::cli {

/// The run's world. With --scene, options that describe the world are refused, and --frames,
/// --dt, --integrator (a registry name), --tolerance and --substeps replace the scene's own
/// when given. Errors name the option or the scene file.
Result<ClothWorldDesc> world_of(const ClothArgs& args);

/// metrics.json's settings of a run of `world` (the divergence left unset).
ClothRunInfo run_info(const ClothWorldDesc& world, const ClothSimulator& sim,
                      const std::string& integrator, const std::string& scene);

}  // namespace animkit::cli
