#include "animkit/cloth/integrator_registry.h"

#include <gtest/gtest.h>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/grid_cloth.h"

#include <set>
#include <string>
#include <variant>

namespace animkit {
namespace {

TEST(IntegratorRegistry, NamesAreUniqueAndFound) {
  std::set<std::string_view> names;
  for (const IntegratorEntry& entry : cloth_integrators()) {
    EXPECT_TRUE(names.insert(entry.name).second) << entry.name;
    ASSERT_EQ(find_integrator(entry.name), &entry);
    EXPECT_EQ(&integrator_entry(entry.defaults), &entry) << entry.name;
    EXPECT_FALSE(validate(entry.defaults)) << entry.name;
    EXPECT_FALSE(entry.summary.empty());
    EXPECT_GE(entry.default_substeps, 1);
  }
  EXPECT_EQ(find_integrator("verlet"), nullptr);
  EXPECT_EQ(cloth_integrators().front().name, "implicit-pcg");  // the lab's default
}

TEST(IntegratorRegistry, EveryKindOfSettingsHasAnEntry) {
  std::set<std::size_t> listed;
  for (const IntegratorEntry& entry : cloth_integrators()) listed.insert(entry.defaults.index());
  EXPECT_EQ(listed.size(), std::variant_size_v<IntegratorSettings>);
}

TEST(IntegratorRegistry, ToleranceIsSharedByTheImplicitIntegrators) {
  for (const IntegratorEntry& entry : cloth_integrators()) {
    IntegratorSettings settings = entry.defaults;
    set_tolerance(settings, 1e-3);
    if (std::holds_alternative<ExplicitEulerSettings>(settings)) {
      EXPECT_FALSE(tolerance_of(settings));
    } else {
      EXPECT_EQ(tolerance_of(settings), 1e-3) << entry.name;
    }
  }
  EXPECT_EQ(integrator_names().find("implicit-pcg, "), 0u);
}

// The state's buffers never move (cloth_simulator.h): the Python module hands out views of them.
// Checked after every step, since a buffer swap would be back in place after an even number.
TEST(IntegratorRegistry, EveryIntegratorKeepsTheStateBuffersInPlace) {
  for (const IntegratorEntry& entry : cloth_integrators()) {
    SimulationOptions options;
    options.integrator = entry.defaults;
    auto sim = ClothSimulator::create(make_grid_cloth({.cells = 4}), options);
    ASSERT_TRUE(sim) << sim.error().message;
    const double* positions = sim->state().positions.data();
    const double* velocities = sim->state().velocities.data();
    for (int step = 0; step < 3; ++step) {
      ASSERT_TRUE(sim->step(1.0 / 60.0)) << entry.name;
      EXPECT_EQ(sim->state().positions.data(), positions) << entry.name << " step " << step;
      EXPECT_EQ(sim->state().velocities.data(), velocities) << entry.name << " step " << step;
    }
  }
}

}  // namespace
}  // namespace animkit
