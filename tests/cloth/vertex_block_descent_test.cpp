#include "animkit/cloth/vertex_block_descent.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../support/crumpled_cloth.h"
#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/integrator_registry.h"
#include "shared_constants.h"

namespace animkit {
namespace {

using testing_support::kFrame;

ClothSimulator simulator(const ClothDesc& desc, const IntegratorSettings& settings) {
  auto sim = ClothSimulator::create(desc, {settings, 1});
  EXPECT_TRUE(sim) << sim.error().message;
  return std::move(*sim);
}

// A 7 x 7 grid with bends along every grid line and dashpots: every term of g.
ClothDesc bent_damped_cloth(double stiffness, double mass = 1.0) {
  const int n = 6;
  ClothDesc desc =
      make_grid_cloth({.cells = n, .mass = mass, .stiffness = stiffness, .damping = 0.5});
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j + 2 <= n; ++j) {
      desc.bends.push_back(
          line_bend(grid_index(n, i, j), grid_index(n, i, j + 1), grid_index(n, i, j + 2), 30.0));
      desc.bends.push_back(
          line_bend(grid_index(n, j, i), grid_index(n, j + 1, i), grid_index(n, j + 2, i), 30.0));
    }
  }
  return desc;
}

using testing_support::crumpled;

class VbdVariants : public testing::TestWithParam<double> {};  // the Chebyshev rho

// The sweep's decrease of g, checked three ways: as the local differences summed it (exact up
// to rounding, never positive), and against g evaluated on its own before and after. The
// latter allows g's own rounding, which is far above eps |g| here: a spring near its rest
// length loses digits in l - L, so g's last bits wander by about 1e-12 |g|.
void expect_every_sweep_decreases_g(const StepReport& report, int frame) {
  for (const IterationRecord& it : report.iterations) {
    const double rounding = 1e-11 * std::abs(it.objective);
    EXPECT_LE(it.objective_after, it.objective + rounding) << "frame " << frame;
    EXPECT_LE(it.decrease, 0.0);
    EXPECT_NEAR(it.decrease, it.objective_after - it.objective,
                1e-8 * std::abs(it.decrease) + rounding);
    EXPECT_LT(it.slope, 0.0);
  }
}

TEST_P(VbdVariants, EverySweepDecreasesTheIncrementalPotential) {
  VbdSettings settings;  // the default tolerance, 1e-6
  settings.max_iterations = 20000;
  settings.chebyshev_rho = GetParam();
  settings.record_iterations = true;
  // Light particles (the springs, not the inertia, shape each local energy), crumpled, with
  // bends and dashpots, and big steps: strongly nonlinear local problems.
  auto sim = simulator(crumpled(bent_damped_cloth(1e4, 1e-3)), settings);
  std::size_t sweeps = 0;
  for (int frame = 0; frame < 10; ++frame) {
    const auto report = sim.step(0.1);
    ASSERT_TRUE(report) << report.error().message;
    EXPECT_TRUE(report->converged);
    expect_every_sweep_decreases_g(*report, frame);
    sweeps += report->iterations.size();
  }
  EXPECT_GT(sweeps, 100u);
}

TEST(VertexBlockDescent, BacktracksALocalStepThatWouldIncreaseG) {
  // A light particle between a very stiff spring B along x, stretched by 1e-6 (so its
  // transverse stiffness k (1 - L/l) is only about 1), and a soft spring A along z pulling it
  // sideways. The local Newton step along z, scaled by that small transverse curvature, goes
  // so far that B, stretched hard, raises g by far more than A lowers it (B's energy grows like
  // k dz^4 / 8). The backtracking must shorten it.
  ClothDesc desc;
  desc.particles = {{Vec3(-1.0, 0.0, 0.0), Vec3::Zero(), 1.0, true},
                    {Vec3(0.0, 0.0, 2.0), Vec3::Zero(), 1.0, true},
                    {Vec3(1e-6, 0.0, 0.0), Vec3::Zero(), 1e-3, false}};
  desc.springs = {{0, 2, 1.0, 1e6}, {1, 2, 1.0, 1.0}};
  desc.gravity = 0.0;
  desc.damping = 0.0;
  VbdSettings settings;
  settings.record_iterations = true;
  auto sim = simulator(desc, settings);
  const auto report = sim.step(0.1);
  ASSERT_TRUE(report);
  EXPECT_TRUE(report->converged);
  ASSERT_FALSE(report->iterations.empty());
  EXPECT_GT(report->iterations.front().line_search_steps, 0);
  EXPECT_GT(report->line_search_steps, 0);
  expect_every_sweep_decreases_g(*report, 0);
}

TEST_P(VbdVariants, ConvergesOnTheLabsClothAndKeepsPinsStill) {
  VbdSettings settings;
  settings.chebyshev_rho = GetParam();
  auto sim = simulator(make_grid_cloth(), settings);
  const Vec3 a = sim.state().position(grid_index(10, 0, 0));
  const Vec3 b = sim.state().position(grid_index(10, 0, 10));
  for (int frame = 0; frame < 120; ++frame) {
    const auto report = sim.step(kFrame);
    ASSERT_TRUE(report);
    EXPECT_TRUE(report->converged) << "frame " << frame;
    EXPECT_LE(report->gradient_norm_end, report->gradient_tolerance);
    ASSERT_EQ(sim.state().position(grid_index(10, 0, 0)), a);
    ASSERT_EQ(sim.state().position(grid_index(10, 0, 10)), b);
    ASSERT_EQ(sim.state().velocity(grid_index(10, 0, 10)), Vec3::Zero());
  }
}

INSTANTIATE_TEST_SUITE_P(Chebyshev, VbdVariants, testing::Values(0.0, VbdSettings{}.chebyshev_rho),
                         [](const auto& param_info) {
                           return param_info.param > 0.0 ? std::string("chebyshev")
                                                         : std::string("plain");
                         });

TEST(VertexBlockDescent, AFreeParticleFallsExactlyUnderGravity) {
  // One particle, no springs: its local Newton step lands on y exactly, in one sweep.
  ClothDesc desc;
  desc.particles = {{Vec3(0.0, 10.0, 0.0), Vec3(0.5, 1.0, 0.0), 2.0, false}};
  auto sim = simulator(desc, VbdSettings{});
  Vec3 x(0.0, 10.0, 0.0), v(0.5, 1.0, 0.0);
  for (int n = 0; n < 100; ++n) {
    const auto report = sim.step(kFrame);
    ASSERT_TRUE(report);
    EXPECT_LE(report->newton_iterations, 1);
    v.y() -= kFrame * desc.gravity;
    x += kFrame * v;
    EXPECT_LT((sim.state().position(0) - x).norm(), 1e-11);
    EXPECT_LT((sim.state().velocity(0) - v).norm(), 1e-9);
  }
}

TEST(VertexBlockDescent, CheckingEveryFewSweepsStopsOnTheSameTest) {
  VbdSettings settings;
  settings.check_interval = 4;
  auto sim = simulator(make_grid_cloth({.damping = 1.0}), settings);
  for (int frame = 0; frame < 30; ++frame) {
    const auto report = sim.step(kFrame);
    ASSERT_TRUE(report);
    EXPECT_TRUE(report->converged);
    EXPECT_LE(report->gradient_norm_end, report->gradient_tolerance);
    EXPECT_EQ(report->newton_iterations % 4, 0) << "frame " << frame;
  }
}

TEST(VertexBlockDescent, ColoursEveryFreeParticleOnce) {
  const auto built = build_cloth(bent_damped_cloth(100.0));
  ASSERT_TRUE(built);
  const VertexBlockDescent integrator(std::make_shared<const ClothModel>(built->model),
                                      VbdSettings{});
  EXPECT_TRUE(is_valid_coloring(integrator.coloring(), cloth_conflict_edges(built->model)));
}

TEST(VertexBlockDescent, SettingsNameTheirProblem) {
  EXPECT_FALSE(VbdSettings{}.validate());
  VbdSettings s;
  s.tolerance = 0.0;
  EXPECT_EQ(s.validate()->message, "tolerance must be in (0, 1), got 0");
  s = {};
  s.max_iterations = 0;
  EXPECT_EQ(s.validate()->message, "max VBD iterations must be at least 1, got 0");
  s = {};
  s.check_interval = 0;
  EXPECT_EQ(s.validate()->message, "VBD check interval must be at least 1, got 0");
  s = {};
  s.chebyshev_rho = 1.0;
  EXPECT_EQ(s.validate()->message, "Chebyshev rho must be in [0, 1), got 1");
  s = {};
  s.gamma = 1.5;
  EXPECT_EQ(s.validate()->message, "local Armijo gamma must be in (0, 1), got 1.5");
  s = {};
  s.max_backtracks = -1;
  EXPECT_EQ(s.validate()->message, "max local backtracks must be at least 0, got -1");
}

}  // namespace
}  // namespace animkit
