// The run loop every shell shares (cloth_run.h): one report per step, the caller's callback
// after each, a diverged step ending the run with its message, a failing callback its error.
#include "animkit/cloth/cloth_run.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "animkit/cloth/grid_cloth.h"

namespace animkit {
namespace {

ClothSimulator simulator(const GridClothOptions& grid, const SimulationOptions& options) {
  auto sim = ClothSimulator::create(make_grid_cloth(grid), options);
  EXPECT_TRUE(sim) << sim.error().message;
  return std::move(*sim);
}

TEST(ClothRun, StepsEveryFrameAndHandsEachToTheCaller) {
  ClothSimulator sim = simulator({.cells = 6}, {});
  std::vector<int> frames;
  const auto run = run_cloth(sim, 12, 1.0 / 60.0,
                             [&](int frame, const ClothSimulator& s, const StepReport& step) {
                               frames.push_back(frame);
                               EXPECT_EQ(s.steps_taken(), frame);
                               EXPECT_TRUE(step.converged);
                               return Result<void>{};
                             });
  ASSERT_TRUE(run) << run.error().message;
  EXPECT_EQ(run->steps.size(), 12u);
  EXPECT_FALSE(run->divergence);
  ASSERT_EQ(frames.size(), 12u);
  EXPECT_EQ(frames.front(), 1);
  EXPECT_EQ(frames.back(), 12);
  EXPECT_EQ(summarize(run->steps).frames, 12);
}

TEST(ClothRun, ADivergedStepEndsTheRunWithItsMessage) {
  // Explicit Euler with one substep blows up on a stiff cloth at frame-sized steps.
  ClothSimulator sim = simulator({.cells = 6, .stiffness = 1e4}, {ExplicitEulerSettings{}, 1});
  const auto run = run_cloth(sim, 600, 1.0 / 30.0);
  ASSERT_TRUE(run) << run.error().message;
  ASSERT_TRUE(run->divergence);
  EXPECT_LT(run->steps.size(), 600u);
  EXPECT_EQ(run->divergence->rfind(
                "the simulation diverged in step " + std::to_string(run->steps.size() + 1), 0),
            0u)
      << *run->divergence;
}

TEST(ClothRun, AFailingCallbackStopsTheRunWithItsError) {
  ClothSimulator sim = simulator({.cells = 6}, {});
  const auto run = run_cloth(
      sim, 10, 1.0 / 60.0, [](int frame, const ClothSimulator&, const StepReport&) -> Result<void> {
        if (frame == 3) return fail("disk full at frame 3");
        return {};
      });
  ASSERT_FALSE(run);
  EXPECT_EQ(run.error().message, "disk full at frame 3");
  EXPECT_EQ(sim.steps_taken(), 3);
}

}  // namespace
}  // namespace animkit
