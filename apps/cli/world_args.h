#pragma once
// `animkit cloth`'s world from the command line: spheres, boxes, capsules and a ground the cloth
// cannot pass through (contact.h, IPC) and the air it moves in (aerodynamics.h). Parsing only: the
// library builds the world (cloth_world.h).
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "animkit/cloth/cloth_world.h"
#include "animkit/core/result.h"

namespace animkit::cli {

struct WorldArgs {
  std::vector<std::string> spheres;   ///< each --sphere "CX,CY,CZ,R" (m)
  std::vector<std::string> boxes;     ///< each --box "CX,CY,CZ,HX,HY,HZ" (m)
  std::vector<std::string> capsules;  ///< each --capsule "CX,CY,CZ,R,H[,AX,AY,AZ]" (m)
  std::optional<double> ground;      ///< --ground Y: a floor the cloth rests on (m)
  double thickness = 2e-3;           ///< --thickness: contact distance dhat (m)
  bool no_self_contact = false;      ///< --no-self-contact
  double friction = 0.3;             ///< --friction: mu of every contact (0: frictionless)
  std::string wind;                  ///< --wind "X,Y,Z" (m/s); empty: still air, no air term
  std::string gust;                  ///< --gust "X,Y,Z" (m/s): the gusts' peak on top of it

  bool any_contact() const {
    return !spheres.empty() || !boxes.empty() || !capsules.empty() || ground.has_value();
  }
};

void add_world_options(CLI::App& command, WorldArgs& args);

/// Puts the options' spheres, boxes, capsules, ground, contact settings and air into `world`.
/// Errors name the option.
Result<void> apply_world_args(const WorldArgs& args, ClothWorldDesc& world);

}  // namespace animkit::cli
