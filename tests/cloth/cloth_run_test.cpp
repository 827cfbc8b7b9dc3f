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

// Records what a sink is handed; fails at `fail_at` ("begin", "frame 2", "finish").
class RecordingSink final : public ClothSink {
 public:
  explicit RecordingSink(std::string fail_at = "") : fail_at_(std::move(fail_at)) {}
  Result<void> begin(const ClothFrame& start, int frames, double dt) override {
    calls.push_back("begin " + std::to_string(start.frame) + " of " + std::to_string(frames));
    EXPECT_EQ(start.step, nullptr);
    EXPECT_GT(dt, 0.0);
    return outcome("begin");
  }
  Result<void> frame(const ClothFrame& frame) override {
    calls.push_back("frame " + std::to_string(frame.frame));
    EXPECT_NE(frame.step, nullptr);
    EXPECT_EQ(frame.simulator.steps_taken(), frame.frame);
    collider_x.push_back(frame.colliders.empty() ? 0.0 : frame.colliders[0].pose().position.x());
    return outcome(calls.back());
  }
  Result<void> finish(const ClothRun& run, const ClothFrame& last) override {
    calls.push_back("finish at " + std::to_string(last.frame) +
                    (run.divergence ? " diverged" : ""));
    return outcome("finish");
  }
  std::vector<std::string> calls;
  std::vector<double> collider_x;

 private:
  Result<void> outcome(const std::string& call) const {
    if (call == fail_at_) return fail("sink failed at " + call);
    return {};
  }
  std::string fail_at_;
};

TEST(ClothRun, SinksSeeTheStartEveryFrameAndTheEndInOrder) {
  ClothSimulator sim = simulator({.cells = 4}, {});
  RecordingSink first, second;
  ClothSink* const sinks[] = {&first, &second};
  const auto run = run_cloth(sim, 3, 1.0 / 60.0, sinks);
  ASSERT_TRUE(run) << run.error().message;
  const std::vector<std::string> expected = {"begin 0 of 3", "frame 1", "frame 2", "frame 3",
                                             "finish at 3"};
  EXPECT_EQ(first.calls, expected);
  EXPECT_EQ(second.calls, expected);
}

TEST(ClothRun, AFailingSinkStopsTheRunAndNoSinkIsFinished) {
  ClothSimulator sim = simulator({.cells = 4}, {});
  RecordingSink first, failing("frame 2");
  ClothSink* const sinks[] = {&first, &failing};
  const auto run = run_cloth(sim, 5, 1.0 / 60.0, sinks);
  ASSERT_FALSE(run);
  EXPECT_EQ(run.error().message, "sink failed at frame 2");
  EXPECT_EQ(first.calls, (std::vector<std::string>{"begin 0 of 5", "frame 1", "frame 2"}));
  EXPECT_EQ(sim.steps_taken(), 2);

  ClothSimulator again = simulator({.cells = 4}, {});
  RecordingSink refusing("begin");
  ClothSink* const one[] = {&refusing};
  EXPECT_FALSE(run_cloth(again, 5, 1.0 / 60.0, one));
  EXPECT_EQ(again.steps_taken(), 0);
}

TEST(ClothRun, ADivergedRunStillFinishesItsSinks) {
  ClothSimulator sim = simulator({.cells = 6, .stiffness = 1e4}, {ExplicitEulerSettings{}, 1});
  RecordingSink sink;
  ClothSink* const sinks[] = {&sink};
  const auto run = run_cloth(sim, 600, 1.0 / 30.0, sinks);
  ASSERT_TRUE(run && run->divergence);
  EXPECT_EQ(sink.calls.back(), "finish at " + std::to_string(run->steps.size()) + " diverged");
}

TEST(ClothRun, SinksSeeTheCollidersWhereTheSolverHasThem) {
  // A ball moving along +x under a sheet, clear of it: the ball the sinks see is on its path.
  ClothWorldDesc desc;
  desc.cloth = GridClothOptions{.cells = 4};
  ColliderDesc ball;
  ball.name = "ball";
  ball.shape = SphereShape{.radius = 0.2};
  ball.motion =
      ScriptedMotion{.initial = {.position = Vec3(0, -3, 0)}, .linear_velocity = Vec3(1, 0, 0)};
  desc.colliders = {ball};
  auto world = build_cloth_world(desc);
  ASSERT_TRUE(world) << world.error().message;
  RecordingSink sink;
  ClothSink* const sinks[] = {&sink};
  ASSERT_TRUE(run_cloth(*world, 3, 0.1, sinks));
  ASSERT_EQ(sink.collider_x.size(), 3u);
  for (int f = 0; f < 3; ++f) EXPECT_NEAR(sink.collider_x[f], 0.1 * (f + 1), 1e-12) << f;
}

}  // namespace
}  // namespace animkit
