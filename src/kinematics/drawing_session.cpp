#include "animkit/kinematics/drawing_session.h"

#include <algorithm>
#include <chrono>
#include <string>

#include "animkit/core/quaternion_math.h"
#include "animkit/core/validation.h"

namespace animkit {

namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const std::size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
  const double upper = values[mid];
  if (values.size() % 2 == 1) return upper;
  const double lower =
      *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid));
  return 0.5 * (lower + upper);
}

}  // namespace

std::optional<Error> DrawingOptions::validate() const {
  if (laps < 1) return Error{"laps must be at least 1, got " + std::to_string(laps)};
  return ik.validate();
}

std::optional<Error> validate_drawing_targets(std::span<const Vec3> targets, int laps,
                                              std::span<const char> pen_down) {
  if (targets.empty()) return Error{"the trajectory has no targets"};
  if (!pen_down.empty() && pen_down.size() != targets.size()) {
    return Error{"the pen list has " + std::to_string(pen_down.size()) + " flags for " +
                 std::to_string(targets.size()) + " targets"};
  }
  const long long frames = static_cast<long long>(targets.size()) * laps;
  if (frames > kMaxDrawingFrames) {
    return Error{std::to_string(laps) + " laps of " + std::to_string(targets.size()) +
                 " targets make " + std::to_string(frames) + " frames, more than the limit of " +
                 std::to_string(kMaxDrawingFrames)};
  }
  for (std::size_t i = 0; i < targets.size(); ++i) {
    if (!is_finite(targets[i])) {
      return Error{"target " + std::to_string(i) + " has a non-finite coordinate " +
                   to_string(targets[i])};
    }
  }
  return std::nullopt;
}

Result<DrawingRun> run_drawing(const Chain& chain, std::span<const Vec3> targets,
                               const DrawingOptions& options, std::span<const char> pen_down) {
  if (auto error = options.validate()) return fail(error->message);
  if (auto error = validate_drawing_targets(targets, options.laps, pen_down)) {
    return fail(error->message);
  }

  const Pose rest = rest_pose(chain);
  DrawingRun run;
  run.frames.reserve(targets.size() * static_cast<std::size_t>(options.laps));
  Pose pose = rest;
  Pose previous = rest;
  for (int lap = 0; lap < options.laps; ++lap) {
    for (std::size_t t = 0; t < targets.size(); ++t) {
      // The lab resets the arm to rest when a shape starts over; cold start does so every frame.
      if (t == 0 || !options.warm_start) pose = rest;
      const auto start = std::chrono::steady_clock::now();
      auto solved = solve_ik(options.solver, chain, pose, targets[t], options.ik);
      const auto stop = std::chrono::steady_clock::now();
      if (!solved) return fail(solved.error().message);

      DrawingFrame frame;
      frame.lap = lap;
      frame.target = targets[t];
      frame.pen_down = pen_down.empty() || pen_down[t] != 0;
      frame.end_effector = pose.end_effector();
      frame.ik = *solved;
      frame.joint_step_rad =
          t == 0 ? 0.0 : largest_rotation_change(previous.local_rotations, pose.local_rotations);
      frame.solve_time_us = std::chrono::duration<double, std::micro>(stop - start).count();
      frame.joint_positions = pose.global_positions;
      run.frames.push_back(std::move(frame));
      previous = pose;
    }
  }
  run.final_pose = pose;
  return run;
}

std::vector<std::vector<Vec3>> drawn_strokes(std::span<const DrawingFrame> frames) {
  std::vector<std::vector<Vec3>> strokes;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (!frames[i].pen_down) continue;
    const bool continues = i > 0 && frames[i - 1].pen_down && frames[i - 1].lap == frames[i].lap;
    if (!continues) strokes.emplace_back();
    strokes.back().push_back(frames[i].end_effector);
  }
  return strokes;
}

DrawingSummary summarize(const DrawingRun& run) {
  DrawingSummary s;
  s.targets = static_cast<int>(run.frames.size());
  if (run.frames.empty()) return s;
  std::vector<double> iterations, times;
  int converged = 0;
  for (const DrawingFrame& f : run.frames) {
    converged += f.ik.converged ? 1 : 0;
    s.unreachable_targets += f.ik.reachable ? 0 : 1;
    iterations.push_back(f.ik.iterations);
    times.push_back(f.solve_time_us);
    s.iterations_mean += f.ik.iterations;
    s.iterations_max = std::max(s.iterations_max, f.ik.iterations);
    s.error_mean += f.ik.error;
    s.error_max = std::max(s.error_max, f.ik.error);
    s.max_joint_step_rad = std::max(s.max_joint_step_rad, f.joint_step_rad);
    s.solve_time_us_mean += f.solve_time_us;
  }
  const double n = static_cast<double>(run.frames.size());
  s.converged_fraction = converged / n;
  s.iterations_mean /= n;
  s.error_mean /= n;
  s.solve_time_us_mean /= n;
  s.iterations_median = median(std::move(iterations));
  s.solve_time_us_median = median(std::move(times));
  return s;
}

}  // namespace animkit
