#pragma once
// A cloth run: the per-frame loop every shell shares (step, stop on divergence, hand each frame
// to the sinks: the output formats, a progress line, a caller's function), and the aggregate
// numbers of a run (the summary the CLI writes and the documentation quotes).
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/cloth_world.h"
#include "animkit/cloth/step_report.h"
#include "animkit/core/result.h"

namespace animkit {

/// Aggregate numbers of a run's steps (see summarize()); all zero for a run of no steps.
struct ClothRunSummary {
  int frames = 0;                       ///< steps taken
  double ms_per_step_median = 0.0;      ///< median wall time of a step (ms)
  double ms_per_step_mean = 0.0;        ///< mean wall time of a step (ms)
  double newton_iterations_mean = 0.0;  ///< per step
  int newton_iterations_max = 0;        ///< most solver iterations any one step took
  double linear_iterations_mean = 0.0;  ///< PCG iterations per step
  double line_search_steps_mean = 0.0;  ///< backtracking reductions per step
  double converged_fraction = 0.0;      ///< steps that reached their gradient tolerance
  double final_energy = 0.0;            ///< total energy after the last step
};

/// Summarizes the reports of a run's steps, in the order they were taken.
ClothRunSummary summarize(std::span<const StepReport> steps);

/// What a run did: one report per step taken and, when a step diverged, its message (the
/// simulator kept the state before that step; the run stopped there).
struct ClothRun {
  std::vector<StepReport> steps;          ///< one per step taken, in order
  std::optional<std::string> divergence;  ///< the diverged step's message; none if none diverged
};

/// One frame as the sinks see it: frame 0 is the state the run starts from, frame k the state
/// after k steps (at time start + k dt).
struct ClothFrame {
  int frame = 0;                    ///< steps of this run taken to reach it (0: the start)
  const ClothSimulator& simulator;  ///< the simulator, in this frame's state
  /// The colliders where the solver has them: on their paths after every converged step, short
  /// of them after a step CCD held one back (what is drawn and cached is where it really is).
  std::span<const Collider> colliders;
  const StepReport* step = nullptr;  ///< the step that led here; null for frame 0
};

/// Receives a run frame by frame: an output format (point cache, OBJ, metrics, glTF, pictures),
/// a progress line, a test's recorder. Each output file is written whole or not at all: a sink
/// keeps what it writes in a temporary until finish() of a run that did not diverge (metrics,
/// which say how a run failed, excepted), and a sink destroyed before that removes it.
class ClothSink {
 public:
  virtual ~ClothSink() = default;
  /// Before the first step: the start (frame 0) and what follows (at most `frames` steps of
  /// `dt` seconds). An error stops the run before it starts.
  virtual Result<void> begin(const ClothFrame& start, int frames, double dt) = 0;
  /// After every step. An error stops the run.
  virtual Result<void> frame(const ClothFrame& frame) = 0;
  /// After the last step, with every report and, for a diverged run, its message; `last` is
  /// the last frame reached (the state before the step that diverged).
  virtual Result<void> finish(const ClothRun& run, const ClothFrame& last) = 0;
  /// When the run fails instead (a sink's error, a caller's stop): drop what was kept (open
  /// temporaries, frames in memory) now, not when the sink is destroyed, which a caller holding
  /// it (Python) may never do.
  virtual void abandon() {}
};

/// Called after every step with the frame number (1-based), the simulator in its new state and
/// the step's report (to write a cache frame, draw a picture, update a progress line). An
/// error stops the run.
using ClothFrameCallback =
    std::function<Result<void>(int frame, const ClothSimulator& sim, const StepReport& step)>;

/// A callable as a sink: frame() calls it; begin() and finish() do nothing.
class CallbackSink final : public ClothSink {
 public:
  /// Wraps `on_frame`; an empty function makes frame() do nothing.
  explicit CallbackSink(ClothFrameCallback on_frame) : on_frame_(std::move(on_frame)) {}
  Result<void> begin(const ClothFrame&, int, double) override { return {}; }
  Result<void> frame(const ClothFrame& frame) override;
  Result<void> finish(const ClothRun&, const ClothFrame&) override { return {}; }

 private:
  ClothFrameCallback on_frame_;
};

/// Advances the world's simulator by `frames` steps of dt seconds, handing the start, every
/// step and the end to each sink in order. A diverged step ends the run (its message in
/// ClothRun::divergence, not an error; the sinks still finish); a failing sink ends it with
/// that sink's error, and every sink is abandoned instead of finished (nothing is written).
Result<ClothRun> run_cloth(ClothWorld& world, int frames, double dt,
                           std::span<ClothSink* const> sinks);

/// The same for a simulator without colliders.
Result<ClothRun> run_cloth(ClothSimulator& sim, int frames, double dt,
                           std::span<ClothSink* const> sinks);

/// The same with one callable as the only sink (or none).
Result<ClothRun> run_cloth(ClothSimulator& sim, int frames, double dt,
                           const ClothFrameCallback& on_frame = {});

}  // namespace animkit
