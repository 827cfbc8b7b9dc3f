// Time per step of the local/global integrator (with and without Chebyshev) against the lab's
// Newton + PCG, in the same run, on the scenes that matter: stiff cotton (101 x 101, k h^2/m
// about 2e4) and the lab's cloth (11 x 11 and 256 x 256), each step solved to a gradient
// tolerance of 1e-2 and 1e-4. Counters: median_ms (median time per step), iterations per step
// (Newton or local/global), converged (fraction of steps that met the tolerance) and, for
// local/global, factor_ms (its one factorization of P, done before the timed steps).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/integrator_registry.h"

namespace {

constexpr double kFrame = 1.0 / 60.0;
constexpr int kWarmUpFrames = 30;  // start timing on a moving, deformed cloth
constexpr int kWindow = 60;        // steps 31 to 90, restored from the warm-up state

enum Scene : long { cotton, lab, lab_256 };

animkit::GridClothOptions scene_options(long scene) {
  switch (scene) {
    case cotton:
      return {.cells = 100,
              .size = 1.0,
              .height = 1.5,
              .mass = 0.15 / (101.0 * 101.0),
              .stiffness = 1000,
              .damping = 0.0,
              .gravity = 9.81};
    case lab_256:
      return {.cells = 255};
    default:
      return {};
  }
}

// The state after the warm-up frames, computed once per scene (by local/global to 1e-4).
const animkit::ClothState& warm_state(long scene) {
  static std::map<long, animkit::ClothState> cache;
  if (auto it = cache.find(scene); it != cache.end()) return it->second;
  animkit::LocalGlobalSettings settings;
  settings.tolerance = 1e-4;
  auto sim = *animkit::ClothSimulator::create(animkit::make_grid_cloth(scene_options(scene)),
                                              {settings, 1});
  for (int f = 0; f < kWarmUpFrames; ++f) (void)sim.step(kFrame);
  return cache[scene] = sim.state();
}

// Arguments: scene, -log10(tolerance).
void run(benchmark::State& state, animkit::IntegratorSettings settings) {
  const long scene = state.range(0);
  animkit::set_tolerance(settings, std::pow(10.0, -static_cast<double>(state.range(1))));
  const animkit::ClothState& warm = warm_state(scene);
  auto sim = *animkit::ClothSimulator::create(animkit::make_grid_cloth(scene_options(scene)),
                                              {settings, 1});
  std::vector<double> ms;
  double iterations = 0, converged = 0, factor_ms = 0;
  for (auto _ : state) {
    if (ms.size() % kWindow == 0) {
      state.PauseTiming();
      (void)sim.set_state(warm);
      if (ms.empty()) factor_ms = sim.step(kFrame)->ms_hessian;  // factorizes P once
      (void)sim.set_state(warm);
      state.ResumeTiming();
    }
    const auto report = sim.step(kFrame);
    if (!report) {
      state.SkipWithError(report.error().message.c_str());
      break;
    }
    ms.push_back(report->ms);
    iterations += report->newton_iterations;
    converged += report->converged ? 1 : 0;
  }
  if (ms.empty()) return;
  const double steps = static_cast<double>(ms.size());
  std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
  state.counters["median_ms"] = ms[ms.size() / 2];
  state.counters["iterations"] = iterations / steps;
  state.counters["converged"] = converged / steps;
  if (std::holds_alternative<animkit::LocalGlobalSettings>(settings)) {
    state.counters["factor_ms"] = factor_ms;
  }
}

animkit::LocalGlobalSettings local_global(bool chebyshev) {
  animkit::LocalGlobalSettings settings;
  settings.chebyshev = chebyshev;
  return settings;
}

void BM_ImplicitPcg(benchmark::State& state) {
  run(state, animkit::find_integrator("implicit-pcg")->defaults);
}
void BM_LocalGlobalChebyshev(benchmark::State& state) {
  run(state, local_global(true));
}
void BM_LocalGlobalPlain(benchmark::State& state) {
  run(state, local_global(false));
}

void scenes(benchmark::internal::Benchmark* b) {
  for (long scene : {cotton, lab, lab_256}) {
    for (long digits : {2L, 4L}) b->Args({scene, digits});
  }
  b->ArgNames({"scene", "tol_digits"})->Unit(benchmark::kMillisecond)->Iterations(20);
}

BENCHMARK(BM_ImplicitPcg)->Apply(scenes);
BENCHMARK(BM_LocalGlobalChebyshev)->Apply(scenes);
BENCHMARK(BM_LocalGlobalPlain)->Apply(scenes);

}  // namespace

BENCHMARK_MAIN();
