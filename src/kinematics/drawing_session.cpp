#include "animkit/kinematics/drawing_session.h"

#include <algorithm>
#include <string>

#include "animkit/core/validation.h"
#include "drawing_loop.h"

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

  DrawingRun run;
  auto final_pose = detail::run_drawing_frames(
      targets, options.laps, options.warm_start, pen_down, rest_pose(chain),
      [&](Pose& pose, const Vec3& target) {
        return solve_ik(options.solver, chain, pose, target, options.ik);
      },
      [](const Pose& pose) { return pose.end_effector(); }, run);
  if (!final_pose) return fail(final_pose.error().message);
  run.final_pose = std::move(*final_pose);
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
