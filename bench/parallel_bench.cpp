// Speedup of the parallel loops (src/core/parallel.h): the same work with 1 and 2 threads in
// one run, on the lab's cloth at 256 x 256 and the cotton sheet at 101 x 101. Kernels (the
// incremental potential's gradient, the Hessian's assembly, a Hessian-vector product) and whole
// steps of the implicit integrators (multigrid included), each to a relative gradient of 1e-2
// (visually converged).
// Results are the same bits for both thread counts, so both time the same iterations. Run with
// --benchmark_repetitions=5: the ratios then compare medians.
#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/incremental_potential.h"
#include "animkit/cloth/integrator_registry.h"
#include "animkit/core/threads.h"
#include "ratio_reporter.h"

namespace {

constexpr double kFrame = 1.0 / 60.0;
constexpr int kWarmUpFrames = 10;  // time a moving, deformed cloth
constexpr int kTimedSteps = 5;
constexpr double kTolerance = 1e-2;

enum Scene : long { kLab256 = 0, kCotton = 1 };
const char* const kSceneNames[] = {"lab256", "cotton101"};

animkit::GridClothOptions scene_options(long scene) {
  if (scene == kLab256) return {.cells = 255};
  return {.cells = 100,
          .size = 1.0,
          .gravity = 9.81,
          .material = animkit::find_material("cotton")->material};
}

// The warm-up state of each scene (local/global, quick on both), computed once per run.
const animkit::ClothState& warmed_up_state(long scene) {
  static std::map<long, animkit::ClothState> cache;
  if (auto it = cache.find(scene); it != cache.end()) return it->second;
  animkit::IntegratorSettings settings = animkit::find_integrator("local-global")->defaults;
  animkit::set_tolerance(settings, kTolerance);
  auto sim = *animkit::ClothSimulator::create(animkit::make_grid_cloth(scene_options(scene)),
                                              {settings, 1});
  for (int f = 0; f < kWarmUpFrames; ++f) (void)sim.step(kFrame);
  return cache.emplace(scene, sim.state()).first->second;
}

void step(benchmark::State& state, std::string_view integrator) {
  const long scene = state.range(0);
  const animkit::ClothState& warm = warmed_up_state(scene);
  animkit::set_thread_count(static_cast<int>(state.range(1)));
  animkit::IntegratorSettings settings = animkit::find_integrator(integrator)->defaults;
  animkit::set_tolerance(settings, kTolerance);
  auto sim = *animkit::ClothSimulator::create(animkit::make_grid_cloth(scene_options(scene)),
                                              {settings, 1});
  (void)sim.set_state(warm);
  for (auto _ : state) {
    if (!sim.step(kFrame)) state.SkipWithError("step failed");
  }
  animkit::set_thread_count(0);
}

void BM_StepImplicitPcg(benchmark::State& state) {
  step(state, "implicit-pcg");
}
// The default for physical sheets: its V-cycle sweeps sheets of 4,096 particles or more in
// chunks over the threads (smoothed_aggregation.h).
void BM_StepImplicitMultigrid(benchmark::State& state) {
  step(state, "implicit-multigrid");
}
void BM_StepVbd(benchmark::State& state) {
  step(state, "vbd");
}
void BM_StepLocalGlobal(benchmark::State& state) {
  step(state, "local-global");
}

enum Kernel { kGradient, kHessian, kMultiply };

void kernel(benchmark::State& state, Kernel which) {
  const long scene = state.range(0);
  const animkit::ClothState& warm = warmed_up_state(scene);
  const auto built = animkit::build_cloth(animkit::make_grid_cloth(scene_options(scene)));
  const animkit::ClothModel& model = built->model;
  animkit::IncrementalPotential potential(model);
  potential.prepare(warm, kFrame);
  const Eigen::VectorXd& x = potential.predicted();
  Eigen::VectorXd out(x.size());
  animkit::BlockHessian hessian(model);
  potential.hessian(x, hessian, true);
  animkit::set_thread_count(static_cast<int>(state.range(1)));
  for (auto _ : state) {
    switch (which) {
      case kGradient:
        potential.gradient(x, out);
        break;
      case kHessian:
        potential.hessian(x, hessian, true);
        break;
      case kMultiply:
        hessian.multiply(model, x, out);
        break;
    }
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  animkit::set_thread_count(0);
}

void BM_Gradient(benchmark::State& state) {
  kernel(state, kGradient);
}
void BM_Hessian(benchmark::State& state) {
  kernel(state, kHessian);
}
void BM_Multiply(benchmark::State& state) {
  kernel(state, kMultiply);
}

void step_args(benchmark::internal::Benchmark* b) {
  for (long scene : {kLab256, kCotton}) {
    for (long threads : {1L, 2L}) b->Args({scene, threads});
  }
  b->ArgNames({"scene", "threads"})->Unit(benchmark::kMillisecond)->Iterations(kTimedSteps);
  b->UseRealTime();
}

void kernel_args(benchmark::internal::Benchmark* b) {
  for (long scene : {kLab256, kCotton}) {
    for (long threads : {1L, 2L}) b->Args({scene, threads});
  }
  b->ArgNames({"scene", "threads"})->Unit(benchmark::kMicrosecond)->UseRealTime();
}

BENCHMARK(BM_Gradient)->Apply(kernel_args);
BENCHMARK(BM_Hessian)->Apply(kernel_args);
BENCHMARK(BM_Multiply)->Apply(kernel_args);
BENCHMARK(BM_StepImplicitPcg)->Apply(step_args);
BENCHMARK(BM_StepImplicitMultigrid)->Apply(step_args);
BENCHMARK(BM_StepVbd)->Apply(step_args);
BENCHMARK(BM_StepLocalGlobal)->Apply(step_args);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  animkit::bench::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  for (const char* name : {"BM_Gradient", "BM_Hessian", "BM_Multiply", "BM_StepImplicitPcg",
                           "BM_StepImplicitMultigrid", "BM_StepVbd", "BM_StepLocalGlobal"}) {
    for (long scene : {kLab256, kCotton}) {
      const std::string base = std::string(name) + "/scene:" + std::to_string(scene);
      reporter.print_ratio(base + "/threads:1", base + "/threads:2", "time",
                           std::string(name) + " " + kSceneNames[scene] + " 1 / 2 threads");
    }
  }
  benchmark::Shutdown();
  return 0;
}
