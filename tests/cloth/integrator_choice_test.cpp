#include "animkit/cloth/integrator_choice.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "animkit/cloth/cloth_world.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/integrator_registry.h"

namespace animkit {
namespace {

TEST(IntegratorChoice, TriesEveryImplicitIntegratorAndPicksAConvergedFastestOne) {
  const auto choice = choose_integrator(make_grid_cloth({.cells = 6}), 1.0 / 60.0, 1e-6);
  ASSERT_TRUE(choice) << choice.error().message;
  std::size_t implicit = 0;
  for (const IntegratorEntry& entry : cloth_integrators())
    implicit += tolerance_of(entry.defaults) ? 1 : 0;
  ASSERT_EQ(choice->trials.size(), implicit);
  const auto winner =
      std::find_if(choice->trials.begin(), choice->trials.end(),
                   [&](const IntegratorTrial& t) { return t.name == choice->name; });
  ASSERT_NE(winner, choice->trials.end());
  EXPECT_TRUE(winner->converged);
  EXPECT_EQ(winner->steps, 3);
  // No other full, converged trial was faster; one stopped early had already spent more.
  for (const IntegratorTrial& trial : choice->trials) {
    EXPECT_FALSE(trial.diverged) << trial.name;
    if (trial.steps == 3 && trial.converged) {
      EXPECT_GE(trial.ms_per_step, winner->ms_per_step);
    }
    EXPECT_GE(trial.steps, 1) << trial.name;
  }
  // The settings are the winner's, at the asked tolerance.
  EXPECT_EQ(integrator_entry(choice->settings).name, choice->name);
  EXPECT_EQ(tolerance_of(choice->settings), 1e-6);
}

TEST(IntegratorChoice, AWorldWithContactTriesOnlyTheIntegratorsThatTakeIt) {
  ClothWorldDesc world;
  world.cloth = GridClothOptions{.cells = 4, .size = 1.0, .height = 0.5, .pins = GridPins::none};
  world.ground = GroundDesc{};
  const auto choice = choose_integrator(world, 1e-4);
  ASSERT_TRUE(choice) << choice.error().message;
  for (const IntegratorTrial& trial : choice->trials) {
    EXPECT_TRUE(find_integrator(trial.name)->takes_energy_terms) << trial.name;
    EXPECT_FALSE(trial.diverged) << trial.name;
  }
  EXPECT_FALSE(choice->trials.empty());
  // The winner runs the world.
  world.simulation.integrator = choice->settings;
  EXPECT_TRUE(build_cloth_world(world));
  // Without contact or air every implicit integrator competes again.
  world.ground.reset();
  const auto free = choose_integrator(world, 1e-4);
  ASSERT_TRUE(free) << free.error().message;
  EXPECT_GT(free->trials.size(), choice->trials.size());
}

// The registry's flag says what ClothSimulator::add_energy_term does.
TEST(IntegratorChoice, TheRegistrySaysWhichIntegratorsTakeEnergyTerms) {
  ClothWorldDesc world;
  world.cloth = GridClothOptions{.cells = 4, .size = 1.0, .height = 0.5, .pins = GridPins::none};
  world.ground = GroundDesc{};
  for (const IntegratorEntry& entry : cloth_integrators()) {
    world.simulation = SimulationOptions{entry.defaults, 0};
    EXPECT_EQ(static_cast<bool>(build_cloth_world(world)), entry.takes_energy_terms) << entry.name;
  }
}

TEST(IntegratorChoice, BadArgumentsNameTheProblem) {
  const ClothDesc scene = make_grid_cloth({.cells = 4});
  const auto no_steps = choose_integrator(scene, 1.0 / 60.0, 1e-6, 0);
  ASSERT_FALSE(no_steps);
  EXPECT_NE(no_steps.error().message.find("trial steps"), std::string::npos);
  const auto bad_dt = choose_integrator(scene, NAN, 1e-6);
  ASSERT_FALSE(bad_dt);
  EXPECT_NE(bad_dt.error().message.find("time step"), std::string::npos) << bad_dt.error().message;
  const auto bad_tolerance = choose_integrator(scene, 1.0 / 60.0, 2.0);
  ASSERT_FALSE(bad_tolerance);
  EXPECT_NE(bad_tolerance.error().message.find("tolerance"), std::string::npos)
      << bad_tolerance.error().message;
}

}  // namespace
}  // namespace animkit
