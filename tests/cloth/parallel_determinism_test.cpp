// The parallel loops (src/core/parallel.h) give the same bits run after run and for any thread
// count: every implicit integrator in the registry, several steps of the lab's cloth, a stiff
// cotton sheet (whose spring loops split), and a lab cloth large enough that every loop splits.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <numeric>
#include <string>
#include <variant>
#include <vector>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/element_schedule.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/integrator_registry.h"
#include "animkit/core/threads.h"

namespace animkit {
namespace {

struct DeterminismScene {
  std::string name;
  GridClothOptions options;
  int steps;
};

GridClothOptions cotton_grid(int cells) {
  return {
      .cells = cells, .size = 1.0, .gravity = 9.81, .material = find_material("cotton")->material};
}

// Restores the default thread count when a test ends, however it ends.
struct ThreadCountGuard {
  ~ThreadCountGuard() { set_thread_count(0); }
};

ClothState run(const DeterminismScene& scene, const IntegratorEntry& entry, int threads) {
  set_thread_count(threads);
  // Visually converged steps keep the stiff scenes quick; the loops run the same either way.
  IntegratorSettings settings = entry.defaults;
  set_tolerance(settings, 1e-2);
  auto sim = ClothSimulator::create(make_grid_cloth(scene.options), {settings, 0});
  EXPECT_TRUE(sim.has_value());
  if (!sim) return {};
  for (int s = 0; s < scene.steps; ++s) {
    const auto report = sim->step(1.0 / 60.0);
    EXPECT_TRUE(report.has_value()) << report.error().message;
  }
  return sim->state();
}

bool same_bits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

class ParallelDeterminism : public testing::TestWithParam<DeterminismScene> {};

TEST_P(ParallelDeterminism, SameBitsForTheSameAndForAnyThreadCount) {
  const ThreadCountGuard guard;
  for (const IntegratorEntry& entry : cloth_integrators()) {
    if (std::holds_alternative<ExplicitEulerSettings>(entry.defaults)) continue;
    SCOPED_TRACE(std::string(entry.name));
    const ClothState first = run(GetParam(), entry, 2);
    const ClothState second = run(GetParam(), entry, 2);
    EXPECT_TRUE(same_bits(first.positions, second.positions));
    EXPECT_TRUE(same_bits(first.velocities, second.velocities));
    // Thread-count independent by design, so exactly equal, not merely close.
    const ClothState serial = run(GetParam(), entry, 1);
    EXPECT_TRUE(same_bits(first.positions, serial.positions));
    EXPECT_TRUE(same_bits(first.velocities, serial.velocities));
  }
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, ParallelDeterminism,
    testing::Values(DeterminismScene{"lab", {}, 5},
                    DeterminismScene{"cotton31", cotton_grid(30), 2},
                    // 4,225 particles: above the parallel threshold in every loop.
                    DeterminismScene{"lab65", {.cells = 64}, 2}),
    [](const testing::TestParamInfo<DeterminismScene>& param) { return param.param.name; });

TEST(ElementSchedule, GridSpringsSplitIntoDisjointBands) {
  const auto built = build_cloth(make_grid_cloth({.cells = 64}));
  ASSERT_TRUE(built.has_value());
  const ElementSchedule schedule(built->model.springs, built->model.particle_count());
  EXPECT_TRUE(schedule.parallel);
  std::vector<int> sorted = schedule.order;
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> all(built->model.springs.size());
  std::iota(all.begin(), all.end(), 0);
  EXPECT_EQ(sorted, all);  // every spring once
}

TEST(ElementSchedule, ScatteredNumberingRunsOnOneThread) {
  // Every element joins particle 0 to a far one: all segments share particle 0.
  std::vector<std::array<int, 2>> springs;
  for (int i = 1; i < 1000; ++i) springs.push_back({0, i});
  EXPECT_FALSE(ElementSchedule(springs, 1000).parallel);
}

TEST(ThreadCount, SetAndRestoreTheDefault) {
  const ThreadCountGuard guard;
  set_thread_count(3);
  EXPECT_EQ(thread_count(), 3);
  set_thread_count(0);
  EXPECT_GE(thread_count(), 1);
}

}  // namespace
}  // namespace animkit
