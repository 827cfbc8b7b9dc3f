// Vertex Block Descent against Newton + PCG on the scenes that matter: the cotton sheet (stiff:
// k h^2 / m ~ 2e4) and the lab's cloth (11 x 11 and 256 x 256), each step solved to a relative
// gradient tolerance of 1e-2 and 1e-4 (the same stopping test for both). Counters: the median
// time per step (ms), solver iterations per step (VBD sweeps or Newton iterations), CG
// iterations per step and the fraction of steps that converged.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/integrator_registry.h"

namespace {

constexpr double kFrame = 1.0 / 60.0;
constexpr int kWarmUpFrames = 20;  // start timing on a moving, deformed cloth
constexpr int kTimedSteps = 10;    // steps 21 to 30 of the fall from flat

enum Scene : long { kCotton = 0, kLab = 1, kLab256 = 2 };

animkit::GridClothOptions scene_options(long scene) {
  switch (scene) {
    case kCotton:
      return {.cells = 100,
              .size = 1.0,
              .height = 1.5,
              .mass = 0.15 / (101.0 * 101.0),
              .stiffness = 1000,
              .damping = 0.0,
              .gravity = 9.81};
    case kLab256:
      return {.cells = 255};
    default:
      return {};
  }
}

// The warm-up state of each scene, computed once per run by Newton + PCG to 1e-4 (the same
// start for every integrator).
const animkit::ClothState& warmed_up_state(long scene) {
  static std::map<long, animkit::ClothState> cache;
  if (auto it = cache.find(scene); it != cache.end()) return it->second;
  animkit::IntegratorSettings settings = animkit::find_integrator("implicit-pcg")->defaults;
  animkit::set_tolerance(settings, 1e-4);
  auto sim = *animkit::ClothSimulator::create(animkit::make_grid_cloth(scene_options(scene)),
                                              {settings, 1});
  for (int f = 0; f < kWarmUpFrames; ++f) (void)sim.step(kFrame);
  return cache.emplace(scene, sim.state()).first->second;
}

void run(benchmark::State& state, std::string_view integrator) {
  const long scene = state.range(0);
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(1)));
  const animkit::ClothState& warm = warmed_up_state(scene);
  animkit::IntegratorSettings settings = animkit::find_integrator(integrator)->defaults;
  animkit::set_tolerance(settings, tolerance);
  auto sim = *animkit::ClothSimulator::create(animkit::make_grid_cloth(scene_options(scene)),
                                              {settings, 1});
  (void)sim.set_state(warm);
  std::vector<double> ms;
  double iterations = 0, cg = 0, converged = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const auto report = sim.step(kFrame);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count());
    if (!report) {
      state.SkipWithError(report.error().message.c_str());
      return;
    }
    iterations += report->newton_iterations;
    cg += report->linear_iterations;
    converged += report->converged ? 1 : 0;
  }
  const auto steps = static_cast<double>(ms.size());
  std::nth_element(ms.begin(), ms.begin() + static_cast<long>(ms.size() / 2), ms.end());
  state.counters["median_ms"] = ms[ms.size() / 2];
  state.counters["iters"] = iterations / steps;
  state.counters["cg"] = cg / steps;
  state.counters["converged"] = converged / steps;
}

void BM_Vbd(benchmark::State& state) {
  run(state, "vbd");
}
void BM_ImplicitPcg(benchmark::State& state) {
  run(state, "implicit-pcg");
}

void scenes(benchmark::internal::Benchmark* b) {
  for (long scene : {kCotton, kLab, kLab256}) {
    for (long digits : {2L, 4L}) b->Args({scene, digits});
  }
  b->ArgNames({"scene", "tol_exp"})->Unit(benchmark::kMillisecond)->Iterations(kTimedSteps);
}

BENCHMARK(BM_Vbd)->Apply(scenes);
BENCHMARK(BM_ImplicitPcg)->Apply(scenes);

}  // namespace

BENCHMARK_MAIN();
