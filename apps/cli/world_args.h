#pragma once
// `animkit cloth`'s world: spheres and a ground the cloth cannot pass through (contact.h, IPC)
// and the air it moves in (aerodynamics.h). Parsing and wiring only: the physics is the
// library's energy terms.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/collision/collider.h"
#include "animkit/core/result.h"

namespace animkit::cli {

struct WorldArgs {
  std::vector<std::string> spheres;  ///< each --sphere "CX,CY,CZ,R" (m)
  std::optional<double> ground;      ///< --ground Y: a floor the cloth rests on (m)
  double thickness = 2e-3;           ///< --thickness: contact distance dhat (m)
  bool no_self_contact = false;      ///< --no-self-contact
  std::string wind;                  ///< --wind "X,Y,Z" (m/s); empty: still air, no air term
  std::string gust;                  ///< --gust "X,Y,Z" (m/s): the gusts' peak on top of it

  bool any_contact() const { return !spheres.empty() || ground.has_value(); }
};

void add_world_options(CLI::App& command, WorldArgs& args);

/// Adds the contact and air terms to `sim`; returns the colliders (for pictures and
/// colliders.obj). Errors name the option, or the particle that starts inside a collider.
Result<std::vector<Collider>> add_world(ClothSimulator& sim, const WorldArgs& args);

}  // namespace animkit::cli
