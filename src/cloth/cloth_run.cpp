#include "animkit/cloth/cloth_run.h"

#include <algorithm>
#include <vector>

namespace animkit {

ClothRunSummary summarize(std::span<const StepReport> steps) {
  ClothRunSummary s;
  s.frames = static_cast<int>(steps.size());
  if (steps.empty()) return s;
  std::vector<double> ms;
  int converged = 0;
  for (const StepReport& r : steps) {
    ms.push_back(r.ms);
    s.ms_per_step_mean += r.ms;
    s.newton_iterations_mean += r.newton_iterations;
    s.newton_iterations_max = std::max(s.newton_iterations_max, r.newton_iterations);
    s.linear_iterations_mean += r.linear_iterations;
    s.line_search_steps_mean += r.line_search_steps;
    converged += r.converged ? 1 : 0;
  }
  const double n = static_cast<double>(steps.size());
  s.ms_per_step_mean /= n;
  s.newton_iterations_mean /= n;
  s.linear_iterations_mean /= n;
  s.line_search_steps_mean /= n;
  s.converged_fraction = converged / n;
  s.final_energy = steps.back().energy;
  std::sort(ms.begin(), ms.end());
  const std::size_t mid = ms.size() / 2;
  s.ms_per_step_median = ms.size() % 2 == 1 ? ms[mid] : 0.5 * (ms[mid - 1] + ms[mid]);
  return s;
}

Result<void> CallbackSink::frame(const ClothFrame& frame) {
  if (!on_frame_) return {};
  return on_frame_(frame.frame, frame.simulator, *frame.step);
}

namespace {

// The loop over any simulator; `pose_colliders` moves `posed` to where the solver has the
// colliders after each step.
template <typename PoseColliders>
Result<ClothRun> run_with_sinks(ClothSimulator& sim, int frames, double dt,
                                std::span<ClothSink* const> sinks, std::vector<Collider>& posed,
                                const PoseColliders& pose_colliders) {
  // A failure leaves nothing behind: every sink drops what it kept.
  const auto failed = [&](const Error& error) -> Result<ClothRun> {
    for (ClothSink* sink : sinks) sink->abandon();
    return fail(error.message);
  };
  ClothRun run;
  // Grown as the steps come (a run may stop early); only a bounded start is reserved.
  run.steps.reserve(static_cast<std::size_t>(std::clamp(frames, 0, 1024)));
  pose_colliders();
  ClothFrame start{.frame = 0, .simulator = sim, .colliders = posed};
  for (ClothSink* sink : sinks) {
    if (auto ok = sink->begin(start, frames, dt); !ok) return failed(ok.error());
  }
  int reached = 0;
  for (int frame = 1; frame <= frames; ++frame) {
    auto report = sim.step(dt);
    if (!report) {
      run.divergence = report.error().message;
      break;
    }
    run.steps.push_back(std::move(*report));
    reached = frame;
    pose_colliders();
    const ClothFrame now{
        .frame = frame, .simulator = sim, .colliders = posed, .step = &run.steps.back()};
    for (ClothSink* sink : sinks) {
      if (auto ok = sink->frame(now); !ok) return failed(ok.error());
    }
  }
  const ClothFrame last{.frame = reached,
                        .simulator = sim,
                        .colliders = posed,
                        .step = run.steps.empty() ? nullptr : &run.steps.back()};
  for (ClothSink* sink : sinks) {
    if (auto ok = sink->finish(run, last); !ok) return failed(ok.error());
  }
  return run;
}

}  // namespace

Result<ClothRun> run_cloth(ClothWorld& world, int frames, double dt,
                           std::span<ClothSink* const> sinks) {
  std::vector<Collider> posed = world.colliders;
  const auto pose_colliders = [&] {
    const double t = world.simulator.state().time;
    for (std::size_t i = 0; i < posed.size(); ++i) {
      if (world.contact) {
        posed[i].set_pose(t, world.contact->collider_pose(i));
      } else {
        posed[i].set_time(t);
      }
    }
  };
  return run_with_sinks(world.simulator, frames, dt, sinks, posed, pose_colliders);
}

Result<ClothRun> run_cloth(ClothSimulator& sim, int frames, double dt,
                           std::span<ClothSink* const> sinks) {
  std::vector<Collider> none;
  return run_with_sinks(sim, frames, dt, sinks, none, [] {});
}

Result<ClothRun> run_cloth(ClothSimulator& sim, int frames, double dt,
                           const ClothFrameCallback& on_frame) {
  CallbackSink sink(on_frame);
  ClothSink* const sinks[] = {&sink};
  return run_cloth(sim, frames, dt, sinks);
}

}  // namespace animkit
