#include "animkit/cloth/integrator_registry.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace animkit
