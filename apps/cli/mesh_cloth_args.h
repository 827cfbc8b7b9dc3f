#pragma once
// `animkit cloth --mesh FILE.obj`: the options that cut a cloth from a triangle mesh.
#include <optional>
#include <string>
#include <vector>

#include "animkit/cloth/mesh_cloth.h"

namespace animkit::cli {

struct MeshClothArgs {
  std::string mesh;                    ///< the OBJ file; empty: the grid
  std::vector<std::string> pins;       ///< each --pin: "I,J,..." (0-based vertex indices)
  std::vector<std::string> pin_boxes;  ///< each --pin-box: "X0,Y0,Z0,X1,Y1,Z1"
};

/// The mesh cloth's options: the OBJ file read, the pins parsed, and either `material` (with
/// the given gravity) or the lab's per-particle parameters. Errors name the file or the option.
Result<MeshClothOptions> mesh_cloth_options(const MeshClothArgs& args,
                                            const std::optional<ClothMaterial>& material,
                                            double mass, double stiffness, double damping,
                                            double gravity);

}  // namespace animkit::cli
