#pragma once
// The one list of cloth integrators. The CLI's --integrator choices, the viewer's menu, the
// benchmarks and the parametrized tests all iterate it; nothing else types integrator names.
#include <span>
#include <string>
#include <string_view>

#include "animkit/cloth/integrator_settings.h"

namespace animkit {

/// One integrator of the registry: its name, help line, default settings and substeps.
struct IntegratorEntry {
  std::string_view name;        ///< what the CLI and the viewer accept, e.g. "implicit-pcg"
  std::string_view summary;     ///< one line for menus and --help
  IntegratorSettings defaults;  ///< its settings when the caller gives only its name
  /// Substeps per step when the caller asks for the default (0): explicit Euler needs many.
  int default_substeps = 1;
  /// Whether the integrator takes extra energy terms (contact, friction, air): Newton's do;
  /// the others minimize the cloth's own energy only (ClothSimulator::add_energy_term).
  bool takes_energy_terms = false;
};

/// Every integrator, the default (the lab's implicit Euler with PCG) first.
std::span<const IntegratorEntry> cloth_integrators();

/// The entry called `name`, or null.
const IntegratorEntry* find_integrator(std::string_view name);

/// The entry whose integrator `settings` selects (never null: every alternative is listed).
const IntegratorEntry& integrator_entry(const IntegratorSettings& settings);

/// "implicit-pcg, implicit-direct, ...", for messages.
std::string integrator_names();

}  // namespace animkit
