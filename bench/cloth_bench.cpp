// Cost of one implicit Euler step of the lab's cloth (n x n grids, lab parameters and stiffness
// 1e4), each step solved until the gradient norm is 1e-6 of its starting value: animkit's
// integrators against the straightforward float version (triplets and a fresh SimplicialLLT
// at every Newton iteration), in the same binary. Prints the ratios at the end.
#include <benchmark/benchmark.h>

#include <string>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/integrator_registry.h"
#include "lab_float_cloth.h"
#include "ratio_reporter.h"

namespace {

constexpr double kFrame = 1.0 / 60.0;
constexpr int kWarmUpFrames = 30;  // start timing on a moving, deformed cloth
// In float the gradient does not get to 1e-6 of its start (float epsilon is 1.2e-7 and g sums
// thousands of terms), so the baseline's Newton loop is capped at 3 iterations, one more than
// animkit needs: it reports how often it converged, and its time per step is then a lower
// bound on what the straightforward way costs.
constexpr int kLabMaxNewton = 3;

animkit::GridClothOptions grid(benchmark::State& state) {
  return {.cells = static_cast<int>(state.range(0)),
          .stiffness = static_cast<double>(state.range(1))};
}

// Every benchmark times the same thing: steps 31 to 90 of the cloth falling from flat (the
// warm-up state is computed once by animkit and restored every kWindow steps, untimed).
constexpr int kWindow = 60;

animkit::ClothState warmed_up_state(benchmark::State& state) {
  auto sim = *animkit::ClothSimulator::create(animkit::make_grid_cloth(grid(state)), {});
  for (int f = 0; f < kWarmUpFrames; ++f) (void)sim.step(kFrame);
  return sim.state();
}

void animkit_step(benchmark::State& state, std::string_view integrator) {
  const animkit::ClothState warm = warmed_up_state(state);
  auto sim = *animkit::ClothSimulator::create(animkit::make_grid_cloth(grid(state)),
                                              {animkit::find_integrator(integrator)->defaults, 0});
  double newton = 0, cg = 0, steps = 0, converged = 0;
  for (auto _ : state) {
    if (static_cast<int>(steps) % kWindow == 0) {
      state.PauseTiming();
      (void)sim.set_state(warm);
      state.ResumeTiming();
    }
    const auto report = sim.step(kFrame);
    if (!report) {
      state.SkipWithError(report.error().message.c_str());
      break;
    }
    newton += report->newton_iterations;
    cg += report->linear_iterations;
    converged += report->converged ? 1 : 0;
    ++steps;
  }
  state.counters["newton"] = newton / steps;
  state.counters["cg"] = cg / steps;
  state.counters["converged"] = converged / steps;
}

void BM_ImplicitPcg(benchmark::State& state) {
  animkit_step(state, "implicit-pcg");
}
void BM_ImplicitDirect(benchmark::State& state) {
  animkit_step(state, "implicit-direct");
}

void BM_LabFloatImplicit(benchmark::State& state) {
  // Warmed up by animkit (the baseline would take minutes on the big grids), then handed over
  // in float.
  const animkit::ClothState warm = warmed_up_state(state);
  const auto built = *animkit::build_cloth(animkit::make_grid_cloth(grid(state)));
  animkit::bench::LabFloatImplicitEuler lab(built.model);
  Eigen::VectorXf x, v;
  double newton = 0, steps = 0, converged = 0;
  for (auto _ : state) {
    if (static_cast<int>(steps) % kWindow == 0) {
      state.PauseTiming();
      x = warm.positions.cast<float>();
      v = warm.velocities.cast<float>();
      state.ResumeTiming();
    }
    const int iterations = lab.step(x, v, static_cast<float>(kFrame), 1e-6f, kLabMaxNewton);
    newton += iterations;
    converged += iterations < kLabMaxNewton ? 1 : 0;
    ++steps;
  }
  state.counters["newton"] = newton / steps;
  state.counters["converged"] = converged / steps;
}

void grids(benchmark::internal::Benchmark* b) {
  for (long stiffness : {100L, 10000L}) {
    for (long cells : {10L, 40L, 80L, 100L}) b->Args({cells, stiffness});
  }
  b->ArgNames({"cells", "k"})->Unit(benchmark::kMillisecond);
}

void small_grids(benchmark::internal::Benchmark* b) {
  for (long stiffness : {100L, 10000L}) {
    for (long cells : {10L, 40L}) b->Args({cells, stiffness});
  }
  b->ArgNames({"cells", "k"})->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_ImplicitPcg)->Apply(grids);
// The direct solver takes about a second per step from 81 x 81 on (847 ms measured), and its
// 30 warm-up steps would make each of those benchmarks minutes long: small grids only.
BENCHMARK(BM_ImplicitDirect)->Apply(small_grids);
BENCHMARK(BM_LabFloatImplicit)->Apply(grids)->MinTime(0.2)->Repetitions(1);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  animkit::bench::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  for (const char* args :
       {"cells:10/k:100", "cells:40/k:100", "cells:80/k:100", "cells:100/k:100", "cells:10/k:10000",
        "cells:40/k:10000", "cells:80/k:10000", "cells:100/k:10000"}) {
    const std::string suffix = std::string("/") + args;
    reporter.print_ratio("BM_LabFloatImplicit" + suffix, "BM_ImplicitPcg" + suffix, "time",
                         std::string("lab float LLT / animkit PCG, time per step, ") + args);
    reporter.print_ratio("BM_ImplicitDirect" + suffix, "BM_ImplicitPcg" + suffix, "time",
                         std::string("animkit direct / animkit PCG, time per step, ") + args);
  }
  benchmark::Shutdown();
  return 0;
}
