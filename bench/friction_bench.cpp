// What friction (friction.h) costs a contact step: a cotton sheet (0.6 m, 21 x 21 particles,
// self-contact on) draped over a sphere on the ground, Newton with multigrid CG to 1e-4, without
// friction, with IPC's friction lagged once per step, and with up to 3 lagging passes. Each
// variant first runs its own 30 frames (the drop and the impact), then times the next 20, one
// step per benchmark iteration. Counters: median ms per step, Newton and CG iterations per step,
// lagging passes per step, and the fraction of steps that converged.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/contact.h"
#include "animkit/cloth/friction.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/integrator_registry.h"
#include "animkit/collision/collider_surface.h"

namespace {

constexpr double kFrame = 1.0 / 60.0;
constexpr int kWarmUpFrames = 30;
constexpr int kTimedSteps = 20;
constexpr double kRadius = 0.25;

animkit::ClothSimulator draped_sheet(int passes) {
  animkit::GridClothOptions grid{.cells = 20, .size = 0.6, .gravity = 9.81};
  grid.height = kRadius + 0.02;
  grid.material = animkit::ClothMaterial{};
  animkit::ClothDesc desc = animkit::make_grid_cloth(grid);
  for (animkit::ParticleDesc& p : desc.particles) {
    p.position.x() -= 0.3;
    p.position.z() -= 0.3;
    p.pinned = false;
  }
  animkit::IntegratorSettings settings = animkit::find_integrator("implicit-multigrid")->defaults;
  animkit::set_tolerance(settings, 1e-4);
  std::get<animkit::NewtonSettings>(settings).max_iterations = 300;
  auto sim = *animkit::ClothSimulator::create(desc, {settings, 1});
  auto contact = *animkit::ContactTerm::create(
      std::make_shared<const animkit::ClothModel>(sim.model()), {},
      {.meshes = {animkit::collider_surface(animkit::SphereShape{kRadius}, 3)},
       .ground_height = -kRadius - 0.01});
  (void)sim.add_energy_term(contact);
  if (passes > 0) {
    auto friction = *animkit::FrictionTerm::create(
        contact, {.obstacles = {0.3}, .ground = 0.3, .self = 0.3, .max_passes = passes});
    (void)sim.add_energy_term(friction);
  }
  return sim;
}

void drape(benchmark::State& state) {
  const int passes = static_cast<int>(state.range(0));
  animkit::ClothSimulator sim = draped_sheet(passes);
  for (int f = 0; f < kWarmUpFrames; ++f) (void)sim.step(kFrame);
  std::vector<double> ms;
  double newton = 0, cg = 0, lagging = 0, converged = 0;
  for (auto _ : state) {
    const auto report = sim.step(kFrame);
    if (!report) {
      state.SkipWithError(report.error().message.c_str());
      break;
    }
    ms.push_back(report->ms);
    newton += report->newton_iterations;
    cg += report->linear_iterations;
    lagging += report->friction_iterations;
    converged += report->converged ? 1 : 0;
  }
  if (ms.empty()) return;
  std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
  const double steps = static_cast<double>(state.iterations());
  state.counters["ms_median"] = ms[ms.size() / 2];
  state.counters["newton"] = newton / steps;
  state.counters["cg"] = cg / steps;
  state.counters["passes"] = lagging / steps;
  state.counters["converged"] = converged / steps;
}

// 0: no friction; 1: lagged at x_n (IPC's default); 3: up to 3 lagging passes.
BENCHMARK(drape)->Arg(0)->Arg(1)->Arg(3)->Iterations(kTimedSteps)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
