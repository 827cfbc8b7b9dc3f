// One Newton linear solve of the "cotton" scene (a 101 x 101 hanging cloth, k h^2 / m about
// 2e4) to a relative residual of 1e-2 and 1e-6: conjugate gradients preconditioned by smoothed
// aggregation multigrid against block Jacobi, in the same binary. The multigrid solve's time
// includes its numeric setup (Galerkin products, coarsest factorization), which every Newton
// iteration pays. Prints the time ratios at the end.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "animkit/cloth/block_jacobi_pcg.h"
#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/incremental_potential.h"
#include "animkit/cloth/multigrid_pcg.h"
#include "ratio_reporter.h"

namespace {

constexpr double kFrame = 1.0 / 60.0;
constexpr int kWarmUpFrames = 30;  // a deformed, hanging cloth

struct CottonSystem {
  animkit::ClothModel model;
  animkit::BlockHessian a;
  Eigen::VectorXd b;
};

const CottonSystem& cotton() {
  static const CottonSystem system = [] {
    const animkit::GridClothOptions g{.cells = 100,
                                      .size = 1.0,
                                      .height = 1.5,
                                      .mass = 0.15 / (101.0 * 101.0),
                                      .stiffness = 1000,
                                      .damping = 0.0,
                                      .gravity = 9.81};
    auto sim = *animkit::ClothSimulator::create(animkit::make_grid_cloth(g), {});
    for (int f = 0; f < kWarmUpFrames; ++f) (void)sim.step(kFrame);
    CottonSystem s{sim.model(), animkit::BlockHessian(sim.model()), {}};
    animkit::IncrementalPotential potential(s.model);
    potential.prepare(sim.state(), kFrame);
    potential.hessian(potential.predicted(), s.a, /*projected=*/true);
    s.b.resize(3 * s.model.particle_count());
    potential.gradient(potential.predicted(), s.b);
    s.b = -s.b;
    return s;
  }();
  return system;
}

template <typename Solver>
void solve(benchmark::State& state) {
  const CottonSystem& system = cotton();
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  Solver solver(system.model);
  Eigen::VectorXd x(system.b.size());
  animkit::PcgResult result;
  for (auto _ : state) {
    result = solver.solve(system.a, system.b, x, tolerance, 10000);
    benchmark::DoNotOptimize(x.data());
  }
  state.counters["iterations"] = result.iterations;
  state.counters["residual"] = result.relative_residual;
  if (!result.converged) state.SkipWithError("did not converge");
}

void BM_MultigridPcg(benchmark::State& state) {
  solve<animkit::MultigridPcg>(state);
}
void BM_BlockJacobiPcg(benchmark::State& state) {
  solve<animkit::BlockJacobiPcg>(state);
}

// Argument: -log10 of the relative residual.
BENCHMARK(BM_MultigridPcg)->ArgName("tol")->Arg(2)->Arg(6)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BlockJacobiPcg)->ArgName("tol")->Arg(2)->Arg(6)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  animkit::bench::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  for (const std::string tol : {"2", "6"}) {
    reporter.print_ratio("BM_BlockJacobiPcg/tol:" + tol, "BM_MultigridPcg/tol:" + tol, "time",
                         "block Jacobi / multigrid time, residual 1e-" + tol);
  }
  benchmark::Shutdown();
  return 0;
}
