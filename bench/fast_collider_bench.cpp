// Colliders far faster than their steps: a ball of radius 0.2 m thrown down at 10 or 100 m/s
// through a 5 x 5 cotton sheet (1 m, 1/30 s steps, 4 frames, the fast contact settings of a
// scene file). What it measures is how long the steps that meet the sheet and carry it along
// take: the sheet has only 25 particles, so those steps should cost milliseconds. The ball is
// a sphere collider (contact with its exact surface: its centre and radius) or, the
// straightforward way, the same ball as a mesh collider of its default tessellation (1,280
// triangles; what every sphere was before); and a box keyframed through the sheet in one
// frame (keyframed_box). Each benchmark iteration builds the world and runs the 4 frames (one
// thread: this is about the step's own cost). Counters: the slowest step's ms and Newton
// iterations (median over the iterations), the whole run's ms, and the fraction of steps that
// converged.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "animkit/cloth/cloth_world.h"
#include "animkit/collision/collider_surface.h"
#include "animkit/core/threads.h"
#include "animkit/io/cloth_scene_file.h"

namespace {

constexpr int kFrames = 4;

std::string ball_scene(int speed) {
  // The ball's lowest point starts 0.8 m (10 m/s) or 2.8 m (100 m/s) above the sheet at y = 1:
  // it meets the sheet in the third or the first step.
  const double height = speed >= 100 ? 4.0 : 2.0;
  return R"({"cloth": {"grid": 4, "size": 1, "height": 1, "material": "cotton", "pins": "none",
                       "offset": [-0.5, 0, 0]},
             "colliders": [{"name": "ball", "radius": 0.2, "position": [0, )" +
         std::to_string(height) + R"(, 0], "velocity": [0, )" + std::to_string(-speed) +
         R"(, 0]}],
             "frames": 4, "dt": 0.0333333})";
}

double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// Runs the scene's 4 frames once per benchmark iteration, from a fresh world, and sets the
// counters described at the top.
void run_frames(benchmark::State& state, const animkit::ClothWorldDesc& desc) {
  animkit::set_thread_count(1);
  std::vector<double> slowest_ms, slowest_newton, run_ms;
  double steps = 0, converged = 0;
  for (auto _ : state) {
    auto world = animkit::build_cloth_world(desc);
    if (!world) {
      state.SkipWithError(world.error().message.c_str());
      break;
    }
    double slowest = 0, newton = 0, total = 0;
    for (int frame = 0; frame < kFrames; ++frame) {
      const auto report = world->simulator.step(desc.time_step);
      if (!report) {
        state.SkipWithError(report.error().message.c_str());
        return;
      }
      if (report->ms > slowest) {
        slowest = report->ms;
        newton = report->newton_iterations;
      }
      total += report->ms;
      steps += 1;
      converged += report->converged ? 1 : 0;
    }
    slowest_ms.push_back(slowest);
    slowest_newton.push_back(newton);
    run_ms.push_back(total);
  }
  animkit::set_thread_count(0);
  if (run_ms.empty()) return;
  state.counters["slowest_step_ms"] = median(slowest_ms);
  state.counters["slowest_step_newton"] = median(slowest_newton);
  state.counters["run_ms"] = median(run_ms);
  state.counters["converged"] = converged / steps;
}

void fast_ball(benchmark::State& state) {
  const int speed = static_cast<int>(state.range(0));
  const bool as_mesh = state.range(1) != 0;
  auto desc = animkit::parse_cloth_scene(ball_scene(speed), "ball.json",
                                         std::filesystem::current_path());
  if (!desc) {
    state.SkipWithError(desc.error().message.c_str());
    return;
  }
  animkit::ColliderShape& shape = desc->colliders.front().shape;
  if (as_mesh) shape = animkit::MeshShape{animkit::collider_surface(shape, 3)};
  run_frames(state, *desc);
}

// A box 0.4 m wide keyframed through the same sheet in the first frame: its bottom from 0.3 m
// above the sheet to 0.9 m below it (36 m/s), then on down at 159 m/s.
void keyframed_box(benchmark::State& state) {
  const auto desc = animkit::parse_cloth_scene(
      R"({"cloth": {"grid": 4, "size": 1, "height": 1, "material": "cotton", "pins": "none",
                    "offset": [-0.5, 0, 0]},
          "colliders": [{"name": "box", "shape": "box", "half_extents": [0.2, 0.2, 0.2],
                         "keyframes": [{"time": 0, "position": [0, 1.5, 0]},
                                       {"time": 0.0333333, "position": [0, 0.3, 0]},
                                       {"time": 1, "position": [0, -5, 0]}]}],
          "frames": 4, "dt": 0.0333333})",
      "box.json", std::filesystem::current_path());
  if (!desc) {
    state.SkipWithError(desc.error().message.c_str());
    return;
  }
  run_frames(state, *desc);
}

BENCHMARK(fast_ball)
    ->ArgNames({"m_per_s", "as_mesh"})
    ->Args({10, 0})
    ->Args({10, 1})
    ->Args({100, 0})
    ->Args({100, 1})
    ->Iterations(5)
    ->Unit(benchmark::kMillisecond);

BENCHMARK(keyframed_box)->Iterations(5)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
