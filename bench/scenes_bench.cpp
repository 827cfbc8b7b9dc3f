// The built-in contact scenes (scene/cloth_scenes.h: drape-sphere, tablecloth, flag,
// spinning-sphere, fold), each run whole twice in the same program: with IPC's settings, the
// reference quality mode (`scenes/NAME/reference`: use_reference_contact_settings), and with
// the scene's own, the fast contact settings (`scenes/NAME`). What it shows is what the scenes
// cost with either, and how far the fast settings' results are from the reference's
// (docs/contact.md, "The fast contact settings").
//
// One benchmark iteration is a whole run from the scene's start, with the default threads (as
// `animkit cloth --scene NAME` runs it): building the world is not timed, nor is the audit after
// each frame, nor the reference's steps that the fast run is compared with. Counters:
//   ms_step, ms_max  median and largest of the steps' own wall time (StepReport::ms);
//   newton           Newton iterations per step (mean);
//   converged        fraction of the steps that met their stopping test;
//   bad_frames       frames that the exact audit (tests/support/world_audit.h: CGAL's predicates
//                    on the cloth against itself and every collider, and the ground) rejects;
//   strain_max       the largest relative stretch of a spring at the last frame, %;
// and for the fast settings:
//   apart_mm_median, apart_mm_max  how far, at most over the particles, each step ends from
//                    the reference taking the same step from the same state, mm: the median
//                    and the largest over the run;
//   apart_mm_last_quarter  the largest of those over the run's last quarter of frames, where
//                    drape-sphere, tablecloth and fold have come to rest;
//   end_apart_mm_max, end_apart_mm_median  how far the last frame's particles are from the
//                    reference run's own last frame (the two runs apart from the start), mm.
// After the table, each scene's ratio of the reference's whole run to the fast one's.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "animkit/scene/cloth_scenes.h"
#include "ratio_reporter.h"
#include "reference_steps.h"
#include "world_audit.h"

namespace {

using animkit::ClothState;
using animkit::ClothWorldDesc;

// How far each particle of `a` is from the same particle of `b`, m.
std::vector<double> particle_distances(const ClothState& a, const ClothState& b) {
  std::vector<double> out(a.positions.size() / 3);
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = (a.position(static_cast<int>(i)) - b.position(static_cast<int>(i))).norm();
  return out;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// The largest relative stretch of a spring (the bends' coupling springs, of no stiffness, left
// out), at the state's positions.
double largest_spring_strain(const animkit::ClothModel& model, const ClothState& state) {
  double largest = 0.0;
  for (int s = 0; s < model.spring_count(); ++s) {
    if (model.stiffness[s] <= 0.0) continue;
    const auto [a, b] = model.springs[s];
    const double length = (state.position(a) - state.position(b)).norm();
    largest = std::max(largest, length / model.rest_length[s] - 1.0);
  }
  return largest;
}

// Each reference run's last state, by scene: what the fast run's end is compared with (the
// reference of a scene is registered, and so runs, before its fast settings).
std::map<std::string, ClothState>& reference_ends() {
  static std::map<std::string, ClothState> ends;
  return ends;
}

void run_scene(benchmark::State& state, const animkit::ClothSceneEntry& entry, bool reference) {
  ClothWorldDesc desc = entry.make();
  if (reference) animkit::use_reference_contact_settings(desc);
  for (auto _ : state) {
    state.PauseTiming();
    auto world = animkit::build_cloth_world(desc);
    if (!world) {
      state.SkipWithError(world.error().message.c_str());
      return;
    }
    animkit::ClothSimulator& sim = world->simulator;
    std::optional<animkit::bench::ReferenceSteps> stepped_reference;
    if (!reference) stepped_reference.emplace(entry.make());
    std::vector<double> ms;
    double apart = -1.0;  // m, once compared
    double newton = 0, converged = 0, apart_last_quarter = 0;
    int bad_frames = 0;
    state.ResumeTiming();
    for (int frame = 1; frame <= desc.frames; ++frame) {
      if (stepped_reference) stepped_reference->step_from(state, sim.state(), desc.time_step);
      const auto report = sim.step(desc.time_step);
      state.PauseTiming();
      if (!report) {
        state.SkipWithError(report.error().message.c_str());
        return;
      }
      ms.push_back(report->ms);
      newton += report->newton_iterations;
      converged += report->converged ? 1 : 0;
      const std::string problem = animkit::audit::world_frame_problem(*world, desc, frame);
      bad_frames += problem.empty() ? 0 : 1;
      if (stepped_reference) {
        apart = stepped_reference->compare(sim.state());
        if (4 * frame > 3 * desc.frames) apart_last_quarter = std::max(apart_last_quarter, apart);
      }
      std::fprintf(stderr, "%s%s frame %d/%d: %.1f ms, %d Newton%s%s%s\n",
                   std::string(entry.name).c_str(), reference ? " (reference)" : "", frame,
                   desc.frames, report->ms, report->newton_iterations,
                   report->converged ? "" : ", NOT converged",
                   apart < 0.0 ? "" : (", " + std::to_string(1e3 * apart) +
                                       " mm from the reference's step").c_str(),
                   problem.empty() ? "" : (", BAD: " + problem).c_str());
      state.ResumeTiming();
    }
    state.PauseTiming();
    const double steps = static_cast<double>(ms.size());
    state.counters["frames"] = steps;
    state.counters["ms_step"] = median(ms);
    state.counters["ms_max"] = *std::max_element(ms.begin(), ms.end());
    state.counters["newton"] = newton / steps;
    state.counters["converged"] = converged / steps;
    state.counters["bad_frames"] = bad_frames;
    state.counters["strain_max"] = 100.0 * largest_spring_strain(sim.model(), sim.state());
    const std::string name(entry.name);
    if (reference) {
      reference_ends()[name] = sim.state();
    } else {
      stepped_reference->report(state);
      state.counters["apart_mm_last_quarter"] = 1e3 * apart_last_quarter;
      if (const auto end = reference_ends().find(name); end != reference_ends().end()) {
        const auto distances = particle_distances(sim.state(), end->second);
        state.counters["end_apart_mm_max"] =
            1e3 * *std::max_element(distances.begin(), distances.end());
        state.counters["end_apart_mm_median"] = 1e3 * median(distances);
      }
    }
    state.ResumeTiming();
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  std::vector<std::string> names;
  for (const animkit::ClothSceneEntry& entry : animkit::cloth_scenes()) {
    if (!entry.make().has_contact()) continue;  // the lab's cloth keeps the lab's solver
    const std::string name = "scenes/" + std::string(entry.name);
    names.push_back(name);
    for (const bool reference : {true, false}) {
      benchmark::RegisterBenchmark(
          (reference ? name + "/reference" : name).c_str(),
          [&entry, reference](benchmark::State& s) { run_scene(s, entry, reference); })
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
    }
  }
  animkit::bench::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  for (const std::string& name : names) {
    reporter.print_ratio(name + "/reference", name, "time",
                         "reference / fast settings, whole run, " + name);
    reporter.print_ratio(name + "/reference", name, "ms_step",
                         "reference / fast settings, median step, " + name);
  }
  benchmark::Shutdown();
}
