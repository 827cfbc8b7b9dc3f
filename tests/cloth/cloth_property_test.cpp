// Property test: random valid cloths (sizes, masses, stiffnesses, damping, gravity, time
// steps across wide ranges) through every implicit integrator, checking what must hold for any
// input: pinned particles never move, the state stays finite, every accepted Newton iteration
// decreases the incremental potential, and a step reported converged met its tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/integrator_registry.h"
#include "animkit/core/validation.h"

namespace animkit {
namespace {

// Every integrator of the registry that solves the implicit step.
std::vector<std::string_view> implicit_integrators() {
  std::vector<std::string_view> names;
  for (const IntegratorEntry& entry : cloth_integrators()) {
    if (tolerance_of(entry.defaults)) names.push_back(entry.name);
  }
  return names;
}

class ClothProperty : public ::testing::TestWithParam<std::string_view> {};

TEST_P(ClothProperty, RandomClothsKeepEveryInvariant) {
  std::mt19937 rng(20261123);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto log_uniform = [&](double lo, double hi) {
    return std::exp(std::log(lo) + unit(rng) * (std::log(hi) - std::log(lo)));
  };
  int steps = 0;
  for (int cloth = 0; cloth < 40; ++cloth) {
    GridClothOptions grid;
    grid.cells = 2 + static_cast<int>(unit(rng) * 9);
    grid.size = log_uniform(0.1, 10.0);
    grid.mass = log_uniform(1e-3, 10.0);
    grid.stiffness = log_uniform(1.0, 1e5);
    grid.damping = unit(rng) < 0.2 ? 0.0 : log_uniform(0.01, 10.0);
    grid.gravity = log_uniform(0.1, 20.0);
    const double dt = log_uniform(1e-3, 0.1);
    IntegratorSettings settings = find_integrator(GetParam())->defaults;
    set_record_iterations(settings, true);
    set_tolerance(settings, 1e-6);
    auto sim = ClothSimulator::create(make_grid_cloth(grid), {settings, 0});
    ASSERT_TRUE(sim) << sim.error().message;
    const Eigen::VectorXd start = sim->state().positions;
    for (int s = 0; s < 15; ++s) {
      const auto report = sim->step(dt);
      ASSERT_TRUE(report) << "cloth " << cloth << " step " << s << ": " << report.error().message;
      ++steps;
      ASSERT_TRUE(all_finite(sim->state().positions) && all_finite(sim->state().velocities));
      for (int i = 0; i < sim->model().particle_count(); ++i) {
        if (!sim->model().pinned[i]) continue;
        EXPECT_EQ(sim->state().position(i), Vec3(start.segment<3>(3 * i)));
        EXPECT_EQ(sim->state().velocity(i), Vec3::Zero());
      }
      for (const IterationRecord& it : report->iterations) {
        EXPECT_LE(it.decrease, 0.0) << "cloth " << cloth << " step " << s;
        EXPECT_LT(it.slope, 0.0);
      }
      if (report->converged) {
        EXPECT_LE(report->gradient_norm_end, report->gradient_tolerance);
      }
      ASSERT_TRUE(std::isfinite(report->energy));
    }
  }
  EXPECT_EQ(steps, 40 * 15);
}

INSTANTIATE_TEST_SUITE_P(Implicit, ClothProperty, ::testing::ValuesIn(implicit_integrators()),
                         [](const auto& param_info) {
                           std::string name(param_info.param);
                           for (char& c : name) c = c == '-' ? '_' : c;
                           return name;
                         });

}  // namespace
}  // namespace animkit
