#include "animkit/cloth/local_global.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/grid_cloth.h"
#include "shared_constants.h"

namespace animkit {
namespace {

using testing_support::kFrame;

LocalGlobalSettings local_global(bool chebyshev, double tolerance = 1e-6) {
  LocalGlobalSettings settings;
  settings.chebyshev = chebyshev;
  settings.tolerance = tolerance;
  settings.max_iterations = 100000;
  settings.record_iterations = true;
  return settings;
}

ClothSimulator local_global_simulator(const ClothDesc& desc, const IntegratorSettings& settings) {
  auto sim = ClothSimulator::create(desc, {settings, 1});
  EXPECT_TRUE(sim) << sim.error().message;
  return std::move(*sim);
}

// Bending elements along every grid line of a (cells + 1)^2 grid: every term of g at once.
void add_bends(ClothDesc& desc, int cells, double stiffness) {
  for (int i = 0; i <= cells; ++i) {
    for (int j = 1; j < cells; ++j) {
      desc.bends.push_back(line_bend(grid_index(cells, i, j - 1), grid_index(cells, i, j),
                                     grid_index(cells, i, j + 1), stiffness));
      desc.bends.push_back(line_bend(grid_index(cells, j - 1, i), grid_index(cells, j, i),
                                     grid_index(cells, j + 1, i), stiffness));
    }
  }
}

// A stiff 7 x 7 cloth crumpled at random (springs keep their flat rest lengths), with bends
// and dashpots: the first steps start far from equilibrium.
ClothDesc crumpled_cloth(double stiffness, double damping) {
  ClothDesc desc = make_grid_cloth({.cells = 6, .stiffness = stiffness, .damping = damping});
  for (SpringDesc& s : desc.springs) {
    s.rest_length = (desc.particles[s.a].position - desc.particles[s.b].position).norm();
  }
  add_bends(desc, 6, 0.1 * stiffness);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (ParticleDesc& p : desc.particles) {
    if (!p.pinned) p.position += Vec3(u(rng), u(rng), u(rng));
  }
  return desc;
}

// g(x_{k+1}) <= g(x_k) for every recorded iteration, checked both with g evaluated on its own
// (allowing its rounding) and with the cancellation-free difference. Returns the iterations.
int expect_monotone(const StepReport& report) {
  for (const IterationRecord& it : report.iterations) {
    EXPECT_LT(it.slope, 0.0);
    EXPECT_LE(it.decrease, 0.0);
    EXPECT_LE(it.objective_after, it.objective + 1e-12 * std::abs(it.objective));
  }
  return static_cast<int>(report.iterations.size());
}

TEST(LocalGlobal, PlainMethodDecreasesGAtEveryIteration) {
  auto sim = local_global_simulator(crumpled_cloth(1e4, 0.5), local_global(false));
  int iterations = 0;
  for (int frame = 0; frame < 20; ++frame) {
    const auto report = sim.step(kFrame);
    ASSERT_TRUE(report) << report.error().message;
    EXPECT_TRUE(report->converged);
    iterations += expect_monotone(*report);
    for (const IterationRecord& it : report->iterations) EXPECT_EQ(it.alpha, 1.0);
  }
  EXPECT_GT(iterations, 100);
}

TEST(LocalGlobal, MonotoneChebyshevDecreasesGAtEveryIterationAndRestarts) {
  // An overestimated spectral radius makes the accelerated iterates overshoot: each one that
  // would raise g is replaced by the plain step and the sequence restarts.
  LocalGlobalSettings settings = local_global(true);
  settings.spectral_radius = 0.9999;
  auto sim = local_global_simulator(crumpled_cloth(1e4, 0.5), settings);
  int accelerated = 0, restarts = 0;
  for (int frame = 0; frame < 20; ++frame) {
    const auto report = sim.step(kFrame);
    ASSERT_TRUE(report) << report.error().message;
    EXPECT_TRUE(report->converged);
    expect_monotone(*report);
    const auto& its = report->iterations;
    for (std::size_t k = 0; k < its.size(); ++k) {
      accelerated += its[k].alpha > 1.0 ? 1 : 0;
      // A plain step after the delay is a restart.
      restarts += k > static_cast<std::size_t>(settings.chebyshev_delay) && its[k].alpha == 1.0;
    }
  }
  EXPECT_GT(accelerated, 0);
  EXPECT_GT(restarts, 0) << "the scene never exercised the restart";
}

TEST(LocalGlobal, DecreasesGAtEveryIterationOnCotton) {
  // Cotton (k h^2 / m near 200 at 11 x 11, bends, pins) is far stiffer relative to its
  // inertia than the crumpled cloth above: plain and monotone Chebyshev still never raise g.
  GridClothOptions cotton{.cells = 10, .size = 1.0, .gravity = 9.81};
  cotton.material = find_material("cotton")->material;
  for (bool chebyshev : {false, true}) {
    SCOPED_TRACE(chebyshev ? "Chebyshev" : "plain");
    // 200 iterations a step, converged or not: past the plain start into the acceleration,
    // without the thousands a tight tolerance takes here.
    LocalGlobalSettings settings = local_global(chebyshev);
    settings.max_iterations = 200;
    auto sim = local_global_simulator(make_grid_cloth(cotton), settings);
    int iterations = 0;
    for (int frame = 0; frame < 3; ++frame) {
      const auto report = sim.step(kFrame);
      ASSERT_TRUE(report) << report.error().message;
      iterations += expect_monotone(*report);
    }
    EXPECT_GT(iterations, 100);
  }
}

TEST(LocalGlobal, ChebyshevTakesFewerIterations) {
  int plain = 0, accelerated = 0;
  for (bool chebyshev : {false, true}) {
    auto sim = local_global_simulator(make_grid_cloth({.cells = 20, .stiffness = 1e4}),
                                      local_global(chebyshev));
    for (int frame = 0; frame < 10; ++frame) {
      const auto report = sim.step(kFrame);
      ASSERT_TRUE(report && report->converged);
      (chebyshev ? accelerated : plain) += report->newton_iterations;
    }
  }
  EXPECT_LT(2 * accelerated, plain);
}

TEST(LocalGlobal, PinnedParticlesNeverMove) {
  auto sim = local_global_simulator(crumpled_cloth(1e4, 0.5), LocalGlobalSettings{});
  const Eigen::VectorXd start = sim.state().positions;
  for (int frame = 0; frame < 30; ++frame) {
    ASSERT_TRUE(sim.step(kFrame));
    for (int i = 0; i < sim.model().particle_count(); ++i) {
      if (!sim.model().pinned[i]) continue;
      ASSERT_EQ(sim.state().position(i), Vec3(start.segment<3>(3 * i)));
      ASSERT_EQ(sim.state().velocity(i), Vec3::Zero());
    }
  }
}

TEST(LocalGlobal, ChangingTheTimeStepRefactorizes) {
  // Frames of alternating lengths: P(h) is refactorized whenever h changes, and each step
  // still lands on Newton's solution.
  const ClothDesc desc = crumpled_cloth(1e4, 0.5);
  const auto built = *build_cloth(desc);
  LocalGlobal integrator(std::make_shared<const ClothModel>(built.model),
                         local_global(true, 1e-10));
  NewtonSettings newton;
  newton.linear_solver = LinearSolverKind::direct;
  newton.tolerance = 1e-10;
  auto reference = local_global_simulator(desc, newton);
  ClothState state = built.state;
  for (double h : {kFrame, kFrame, 0.5 * kFrame, 0.05, kFrame}) {
    StepReport report;
    integrator.step(state, h, report, nullptr);
    EXPECT_EQ(integrator.system().factorized_h(), h);
    EXPECT_TRUE(report.converged);
    ASSERT_TRUE(reference.step(h));
    const Eigen::VectorXd& x = reference.state().positions;
    EXPECT_LE((state.positions - x).norm(), 1e-8 * x.norm()) << "h = " << h;
  }
}

TEST(LocalGlobal, RejectsBadSettings) {
  LocalGlobalSettings bad;
  bad.spectral_radius = 1.0;
  EXPECT_EQ(bad.validate()->message, "Chebyshev spectral radius must be in (0, 1), got 1");
  bad = {};
  bad.max_iterations = 0;
  EXPECT_EQ(bad.validate()->message, "max local/global iterations must be at least 1, got 0");
  bad = {};
  bad.chebyshev_delay = -1;
  EXPECT_EQ(bad.validate()->message, "Chebyshev delay must be at least 0, got -1");
  EXPECT_FALSE(LocalGlobalSettings{}.validate());
}

}  // namespace
}  // namespace animkit
