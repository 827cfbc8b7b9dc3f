// The drape benchmark: drape-sphere (drape_scene.h) with self-contact, a cotton sheet falling
// onto a ball on the ground, run by animkit at 41 x 41 and 101 x 101 particles and by Bullet's
// soft body (bullet_drape.h) at 41 x 41, in the same program. animkit runs with IPC's settings
// (use_reference_contact_settings: the reference quality mode), with the fast contact settings
// that the built-in scenes use (`/fast`), and with variants between the two.
//
// One benchmark iteration is a whole run from the flat sheet: building the world is not timed,
// nor is the audit after each frame. Counters:
//   ms_step       median over the run's frames of one frame's wall time (animkit: the step's
//                 own report; Bullet: its stepSimulation), ms_max their largest;
//   cpu_ms_step   the same median in the process's CPU time (both threads), steadier than
//                 wall time when other programs share the cores;
//   newton, cg    animkit's Newton and PCG iterations per step (mean);
//   converged     fraction of animkit's steps that met their stopping test;
//   bad_frames    frames where the cloth intersects itself or the ball's tessellation (the
//                 mesh animkit's contact sees) by the exact CGAL audit
//                 (tests/support/intersection_audit.h), or has a vertex on or below the ground;
//                 self_frames, ball_frames, ground_frames count each kind;
//   ball_depth_mm, ground_depth_mm  the deepest any vertex went inside the true sphere or
//                 below the ground over the run (0 when none did);
//   strain_mean, strain_max  relative stretch of the axis edges at the last frame, %;
//   apart_mm_median, apart_mm_max  (variants with `compare`) how far, at most over the
//                 particles, each step ends from the reference (IPC's settings) taking the
//                 same step from the same state, mm: the median and the largest over the run.
// Each frame also prints one line on stderr (a long run still tells where it is and what its
// steps took if it is stopped). The 101 x 101 run is bounded (kFrames101) so one repetition stays
// within minutes.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "animkit/cloth/cloth_world.h"
#include "animkit/cloth/grid_cloth.h"
#include "bullet_drape.h"
#include "drape_scene.h"
#include "intersection_audit.h"
#include "ratio_reporter.h"
#include "reference_steps.h"

namespace {

using animkit::TriangleMesh;
using animkit::Vec3;

/// Frames of the 101 x 101 run (of the scene's 90): the fall onto the ball (about 4 frames)
/// and the impact, the costliest steps; the whole run takes too long for one repetition.
constexpr int kFrames101 = 10;

// The process's CPU time, ms: on a loaded machine a step's wall time counts other programs'
// turns too (all threads of the process are summed, the pool workers' spinning included).
double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

struct Audit {
  int self = 0, ball = 0, ground = 0, bad = 0;
  double ball_depth = 0.0, ground_depth = 0.0;  // deepest vertex inside the true sphere, ground

  void frame(const TriangleMesh& cloth, const TriangleMesh& ball_surface,
             const animkit::bench::DrapeParts& parts) {
    const double ground_height = parts.ground_height;
    for (const Vec3& v : cloth.vertices) {
      ball_depth = std::max(ball_depth, parts.ball_radius - (v - parts.ball_centre).norm());
      ground_depth = std::max(ground_depth, ground_height - v.y());
    }
    const bool crosses_self = animkit::audit::count_self_intersections(cloth) > 0;
    const bool meets_ball = animkit::audit::meshes_intersect(cloth, ball_surface);
    const bool under_ground = std::any_of(cloth.vertices.begin(), cloth.vertices.end(),
                                          [&](const Vec3& v) { return v.y() <= ground_height; });
    self += crosses_self;
    ball += meets_ball;
    ground += under_ground;
    bad += crosses_self || meets_ball || under_ground;
  }

  void report(benchmark::State& state) const {
    state.counters["bad_frames"] = bad;
    state.counters["self_frames"] = self;
    state.counters["ball_frames"] = ball;
    state.counters["ground_frames"] = ground;
    state.counters["ball_depth_mm"] = 1e3 * ball_depth;
    state.counters["ground_depth_mm"] = 1e3 * ground_depth;
  }
};

void report_times(benchmark::State& state, std::vector<double> ms, std::vector<double> cpu) {
  std::sort(ms.begin(), ms.end());
  std::sort(cpu.begin(), cpu.end());
  state.counters["ms_step"] = ms[ms.size() / 2];
  state.counters["ms_max"] = ms.back();
  state.counters["cpu_ms_step"] = cpu[cpu.size() / 2];
  state.counters["frames"] = static_cast<double>(ms.size());
}

// Relative stretch of the grid's axis edges, mean and largest.
std::array<double, 2> grid_axis_strain(const std::vector<Vec3>& x, int cells, double spacing) {
  double sum = 0.0, largest = 0.0;
  int count = 0;
  for (int i = 0; i <= cells; ++i) {
    for (int j = 0; j <= cells; ++j) {
      const int p = animkit::grid_index(cells, i, j);
      for (const int q : {i < cells ? animkit::grid_index(cells, i + 1, j) : -1,
                          j < cells ? animkit::grid_index(cells, i, j + 1) : -1}) {
        if (q < 0) continue;
        const double strain = (x[p] - x[q]).norm() / spacing - 1.0;
        sum += strain;
        largest = std::max(largest, strain);
        ++count;
      }
    }
  }
  return {sum / count, largest};
}

void report_strain(benchmark::State& state, std::array<double, 2> strain) {
  state.counters["strain_mean"] = 100.0 * strain[0];
  state.counters["strain_max"] = 100.0 * strain[1];
}

// A variant: the solver settings it runs with (the scene's own are the fast contact settings).
struct Variant {
  void (*settings)(animkit::ClothWorldDesc&) = animkit::use_reference_contact_settings;
  /// Also steps the reference (IPC's settings, use_reference_contact_settings) from every
  /// state the variant reached and reports how far apart the two end.
  bool compare = false;
};

void animkit_drape(benchmark::State& state, int particles, int frames, Variant variant = {}) {
  animkit::ClothWorldDesc desc = animkit::bench::drape_world(particles, frames);
  variant.settings(desc);
  const auto& grid = std::get<animkit::GridClothOptions>(desc.cloth);
  const animkit::bench::DrapeParts parts = animkit::bench::drape_parts(desc);
  for (auto _ : state) {
    state.PauseTiming();
    auto world = animkit::build_cloth_world(desc);
    if (!world) {
      state.SkipWithError(world.error().message.c_str());
      return;
    }
    animkit::ClothSimulator& sim = world->simulator;
    const animkit::Collider& ball = world->colliders.front();
    const TriangleMesh ball_surface{ball.world_vertices(), ball.model().surface.triangles};
    TriangleMesh cloth{{}, sim.model().triangles};
    std::vector<double> ms, cpu;
    double newton = 0, cg = 0, converged = 0;
    Audit audit;
    std::optional<animkit::bench::ReferenceSteps> reference;
    if (variant.compare) reference.emplace(animkit::bench::drape_world(particles, frames));
    state.ResumeTiming();
    for (int frame = 1; frame <= desc.frames; ++frame) {
      if (reference) reference->step_from(state, sim.state(), desc.time_step);
      const double cpu0 = cpu_ms();
      const auto report = sim.step(desc.time_step);
      const double cpu1 = cpu_ms();
      state.PauseTiming();
      cpu.push_back(cpu1 - cpu0);
      if (!report) {
        state.SkipWithError(report.error().message.c_str());
        return;
      }
      ms.push_back(report->ms);
      newton += report->newton_iterations;
      cg += report->linear_iterations;
      converged += report->converged ? 1 : 0;
      cloth.vertices.resize(sim.model().particle_count());
      for (int i = 0; i < sim.model().particle_count(); ++i)
        cloth.vertices[i] = sim.state().position(i);
      audit.frame(cloth, ball_surface, parts);
      if (reference) {
        const double apart = reference->compare(sim.state());
        std::fprintf(stderr, "%.3f mm from the reference; ", 1e3 * apart);
      }
      std::fprintf(stderr,
                   "animkit %dx%d frame %d/%d: %.1f ms (cpu %.1f), %d Newton, %d CG, "
                   "|dx|/h %.2g m/s, %d backtracks, %d lagging passes, ms: hessian %.0f, "
                   "solve %.0f, line search %.0f, bound %.0f, updates %.0f, gradient %.0f, "
                   "%s, %d bad frames so far\n",
                   particles, particles, frame, desc.frames, report->ms, cpu.back(),
                   report->newton_iterations, report->linear_iterations, report->newton_speed_end,
                   report->line_search_steps, report->friction_iterations, report->ms_hessian,
                   report->ms_linear_solve, report->ms_line_search, report->ms_step_bound,
                   report->ms_term_updates, report->ms_gradient,
                   report->converged ? "converged" : "NOT converged", audit.bad);
      state.ResumeTiming();
    }
    state.PauseTiming();
    const double steps = static_cast<double>(ms.size());
    report_times(state, ms, cpu);
    state.counters["newton"] = newton / steps;
    state.counters["cg"] = cg / steps;
    if (reference) reference->report(state);
    state.counters["converged"] = converged / steps;
    audit.report(state);
    report_strain(state, grid_axis_strain(cloth.vertices, grid.cells, grid.size / grid.cells));
    state.ResumeTiming();
  }
}

// `margin`: Bullet's collision margin, m; 0 for animkit's contact thickness.
void bullet_drape(benchmark::State& state, int particles, int frames, double margin,
                  bool self_collision = true) {
  const animkit::ClothWorldDesc desc = animkit::bench::drape_world(particles, frames);
  const animkit::bench::DrapeParts parts = animkit::bench::drape_parts(desc);
  animkit::bench::BulletDrapeSettings settings;
  settings.margin = margin > 0.0 ? margin : desc.contact.thickness;
  settings.self_collision = self_collision;
  for (auto _ : state) {
    state.PauseTiming();
    // The animkit world gives the ball's tessellation and the sheet's corners.
    auto world = animkit::build_cloth_world(desc);
    if (!world) {
      state.SkipWithError(world.error().message.c_str());
      return;
    }
    const animkit::Collider& ball = world->colliders.front();
    const TriangleMesh ball_surface{ball.world_vertices(), ball.model().surface.triangles};
    const int n = parts.sheet.cells;
    const animkit::ClothState& start = world->simulator.state();
    const std::array<Vec3, 4> corners{
        start.position(animkit::grid_index(n, 0, 0)), start.position(animkit::grid_index(n, n, 0)),
        start.position(animkit::grid_index(n, 0, n)), start.position(animkit::grid_index(n, n, n))};
    animkit::bench::BulletDrape bullet(parts, corners, settings);
    TriangleMesh cloth{{}, bullet.triangles()};
    std::vector<double> ms, cpu;
    Audit audit;
    state.ResumeTiming();
    for (int frame = 1; frame <= desc.frames; ++frame) {
      const double cpu0 = cpu_ms();
      const auto t0 = std::chrono::steady_clock::now();
      bullet.step(desc.time_step);
      const auto t1 = std::chrono::steady_clock::now();
      const double cpu1 = cpu_ms();
      state.PauseTiming();
      ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
      cpu.push_back(cpu1 - cpu0);
      bullet.positions(cloth.vertices);
      audit.frame(cloth, ball_surface, parts);
      state.ResumeTiming();
    }
    state.PauseTiming();
    report_times(state, ms, cpu);
    audit.report(state);
    report_strain(state, bullet.axis_strain());
    state.ResumeTiming();
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  const int whole = animkit::bench::drape_world(41, 1'000'000).frames;
  benchmark::RegisterBenchmark("drape/animkit/41x41",
                               [whole](benchmark::State& s) { animkit_drape(s, 41, whole); })
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond);
  // The fast contact settings (the scene's own, docs/contact.md), one of their choices alone
  // on IPC's settings, and a Newton cap; each beside the reference.
  const std::pair<const char*, Variant> variants[] = {
      {"fast", {[](animkit::ClothWorldDesc&) {}, true}},
      {"fast/cap20",
       {[](animkit::ClothWorldDesc& d) {
          std::get<animkit::NewtonSettings>(d.simulation.integrator).max_iterations = 20;
        },
        true}},
      {"velocity_stop", {[](animkit::ClothWorldDesc& d) {
         animkit::use_reference_contact_settings(d);
         std::get<animkit::NewtonSettings>(d.simulation.integrator).velocity_tolerance = 1e-3;
       }}},
      {"gauss_newton", {[](animkit::ClothWorldDesc& d) {
         animkit::use_reference_contact_settings(d);
         d.contact.hessian = animkit::BarrierHessian::gauss_newton;
       }}},
  };
  for (const auto& [name, variant] : variants) {
    benchmark::RegisterBenchmark(
        (std::string("drape/animkit/41x41/") + name).c_str(),
        [whole, variant](benchmark::State& s) { animkit_drape(s, 41, whole, variant); })
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::RegisterBenchmark("drape/bullet/41x41",
                               [whole](benchmark::State& s) { bullet_drape(s, 41, whole, 0.0); })
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond);
  // Bullet with a margin of 0.4 grid spacings (1 cm), closer to how it is usually set up: a
  // wider margin keeps its nodes further from the surfaces it resolves in velocity.
  benchmark::RegisterBenchmark("drape/bullet/41x41/margin_1cm",
                               [whole](benchmark::State& s) { bullet_drape(s, 41, whole, 0.01); })
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond);
  // Without self-collision: what Bullet's clusters cost and what they do to the contacts.
  benchmark::RegisterBenchmark(
      "drape/bullet/41x41/no_self_collision",
      [whole](benchmark::State& s) { bullet_drape(s, 41, whole, 0.0, false); })
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("drape/animkit/101x101",
                               [](benchmark::State& s) { animkit_drape(s, 101, kFrames101); })
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond);
  // The fast settings without the reference beside them (whose impact steps take minutes here).
  Variant fast = variants[0].second;
  fast.compare = false;
  benchmark::RegisterBenchmark(
      "drape/animkit/101x101/fast",
      [fast](benchmark::State& s) { animkit_drape(s, 101, kFrames101, fast); })
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond);
  animkit::bench::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_ratio("drape/animkit/41x41", "drape/animkit/41x41/fast", "ms_step",
                       "reference / fast settings, median ms per step, drape 41x41");
  reporter.print_ratio("drape/animkit/41x41", "drape/animkit/41x41/fast", "time",
                       "reference / fast settings, whole run, drape 41x41");
  reporter.print_ratio("drape/bullet/41x41", "drape/animkit/41x41/fast", "ms_step",
                       "Bullet / animkit (fast settings), median ms per step, drape 41x41");
  benchmark::Shutdown();
  return 0;
}
