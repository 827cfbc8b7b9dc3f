// The stiff-cloth table: every implicit integrator of the registry on the scenes that matter, each
// against Newton + block-Jacobi PCG (implicit-pcg, the lab's solver) in the same run:
//   cotton: 1 m x 1 m, 101 x 101, the cotton preset (0.15 kg/m^2, 1000 N/m), pinned at two
//           corners, dt 1/60, to 1e-2 and to 1e-4 relative gradient;
//   lab:    the lab's cloth (per-particle parameters) at 256 x 256 and 11 x 11, to 1e-6.
// Each benchmark runs the cloth's first steps falling from flat (the sheet folds between its
// pins within them) as one iteration per step, and reports the median and the maximum of the
// per-step times (the benchmark's own "time" is their mean) and the fraction of steps that
// converged. Integrators added to the registry join automatically.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>
#include <vector>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/integrator_registry.h"
#include "animkit/cloth/material.h"
#include "ratio_reporter.h"

namespace {

constexpr double kFrame = 1.0 / 60.0;

struct Scene {
  std::string name;
  animkit::GridClothOptions grid;
  double tolerance;
  int steps;  // timed, from flat
};

std::vector<Scene> scenes() {
  animkit::GridClothOptions cotton{.cells = 100, .size = 1.0, .gravity = 9.81};
  cotton.material = animkit::find_material("cotton")->material;
  return {{"cotton101_tol1e-2", cotton, 1e-2, 30},
          {"cotton101_tol1e-4", cotton, 1e-4, 30},
          {"lab256", {.cells = 255}, 1e-6, 30},
          {"lab11", {.cells = 10}, 1e-6, 2000}};
}

void run_steps(benchmark::State& state, const Scene& scene, const animkit::IntegratorEntry& entry) {
  animkit::SimulationOptions options{entry.defaults, 0};
  animkit::set_tolerance(options.integrator, scene.tolerance);
  auto sim = animkit::ClothSimulator::create(animkit::make_grid_cloth(scene.grid), options);
  if (!sim) {
    state.SkipWithError(sim.error().message.c_str());
    return;
  }
  std::vector<double> ms;
  double converged = 0, iterations = 0;
  for (auto _ : state) {
    const auto report = sim->step(kFrame);
    if (!report) {
      state.SkipWithError(report.error().message.c_str());
      return;
    }
    ms.push_back(report->ms);
    converged += report->converged ? 1 : 0;
    iterations += report->newton_iterations;
  }
  std::sort(ms.begin(), ms.end());
  const double steps = static_cast<double>(ms.size());
  state.counters["ms_median"] = ms[ms.size() / 2];
  state.counters["ms_max"] = ms.back();
  state.counters["converged"] = converged / steps;
  state.counters["iterations"] = iterations / steps;
}

std::string benchmark_name(const Scene& scene, std::string_view integrator) {
  return scene.name + "/" + std::string(integrator);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  const std::vector<Scene> all = scenes();
  for (const Scene& scene : all) {
    for (const animkit::IntegratorEntry& entry : animkit::cloth_integrators()) {
      if (!animkit::tolerance_of(entry.defaults)) continue;  // explicit Euler: not comparable
      // The sparse direct solver takes seconds per step beyond 10^4 particles.
      if (entry.name == "implicit-direct" && scene.grid.cells > 50) continue;
      benchmark::RegisterBenchmark(
          benchmark_name(scene, entry.name).c_str(),
          [&scene, &entry](benchmark::State& state) { run_steps(state, scene, entry); })
          ->Iterations(scene.steps)
          ->Unit(benchmark::kMillisecond);
    }
  }
  animkit::bench::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  for (const Scene& scene : all) {
    for (const animkit::IntegratorEntry& entry : animkit::cloth_integrators()) {
      if (!animkit::tolerance_of(entry.defaults) || entry.name == "implicit-pcg") continue;
      reporter.print_ratio(
          benchmark_name(scene, "implicit-pcg"), benchmark_name(scene, entry.name), "ms_median",
          "implicit-pcg / " + std::string(entry.name) + ", median ms per step, " + scene.name);
    }
  }
  benchmark::Shutdown();
  return 0;
}
