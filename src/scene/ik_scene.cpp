#include "animkit/scene/ik_scene.h"

#include <cassert>
#include <chrono>
#include <string>

#include "animkit/core/validation.h"

namespace animkit {

namespace {
std::optional<Error> check_trajectory(const Trajectory& trajectory) {
  const auto& targets = trajectory.targets;
  if (targets.empty()) return Error{"the target list is empty"};
  if (!trajectory.pen_down.empty() && trajectory.pen_down.size() != targets.size()) {
    return Error{"the pen list has " + std::to_string(trajectory.pen_down.size()) + " flags for " +
                 std::to_string(targets.size()) + " targets"};
  }
  for (std::size_t i = 0; i < targets.size(); ++i) {
    if (!is_finite(targets[i])) {
      return Error{"target " + std::to_string(i) + " has a non-finite coordinate " +
                   to_string(targets[i])};
    }
  }
  return std::nullopt;
}
}  // namespace

IkScene::IkScene(Chain chain, Trajectory trajectory, const IkSceneOptions& options)
    : chain_(std::move(chain)),
      pose_(rest_pose(chain_)),
      trajectory_(std::move(trajectory)),
      options_(options) {}

Result<IkScene> IkScene::create(const ChainDesc& desc, Trajectory trajectory,
                                const IkSceneOptions& options) {
  if (auto error = options.ik.validate()) return fail(error->message);
  if (auto error = check_trajectory(trajectory)) return fail(error->message);
  auto chain = build_chain(desc);
  if (!chain) return fail(chain.error().message);
  return IkScene(std::move(*chain), std::move(trajectory), options);
}

void IkScene::reset() {
  pose_ = rest_pose(chain_);
  path_.clear();
  next_ = 0;
  solved_in_lap_ = 0;
  last_.reset();
}

IkSolveReadout IkScene::solve(const Vec3& target) {
  const auto start = std::chrono::steady_clock::now();
  auto result = solve_ik(options_.solver, chain_, pose_, target, options_.ik);
  const auto stop = std::chrono::steady_clock::now();
  // The chain, the options and the target were validated and the pose is ours, so the solver
  // has nothing to reject.
  assert(result.has_value());
  IkSolveReadout readout{target, result.value_or(IkResult{}),
                         std::chrono::duration<double, std::micro>(stop - start).count()};
  last_ = readout;
  return readout;
}

const IkSolveReadout& IkScene::advance() {
  if (lap_finished()) {
    pose_ = rest_pose(chain_);
    path_.clear();
    solved_in_lap_ = 0;
  }
  const auto& pen = trajectory_.pen_down;
  const bool down = pen.empty() || pen[next_] != 0;
  const bool was_down = next_ > 0 && (pen.empty() || pen[next_ - 1] != 0);
  solve(trajectory_.targets[next_]);
  if (down) {
    if (!was_down || path_.empty()) path_.emplace_back();
    path_.back().push_back(pose_.end_effector());
  }
  ++solved_in_lap_;
  next_ = (next_ + 1) % static_cast<int>(trajectory_.targets.size());
  return *last_;
}

Result<IkSolveReadout> IkScene::follow(const Vec3& target) {
  if (!is_finite(target)) return fail("target has a non-finite coordinate " + to_string(target));
  return solve(target);
}

Result<void> IkScene::set_trajectory(Trajectory trajectory) {
  if (auto error = check_trajectory(trajectory)) return fail(error->message);
  trajectory_ = std::move(trajectory);
  reset();
  return {};
}

void describe_arm_drawing(DrawList& out, const ArmDrawingView& view) {
  // The grid sits just below the drawing plane y = 0 so the path never fights it for depth.
  out.add_ground_grid(-0.002, 12, 0.25, 0.5);
  for (std::size_t i = 0; i < view.targets.size(); ++i) {
    if (view.pen_down.empty() || view.pen_down[i] != 0) {
      out.add_point(view.targets[i], palette::target, 5.0f);
    } else {
      out.add_point(view.targets[i], palette::pen_up, 3.0f);
    }
  }
  for (const auto& stroke : view.path) out.add_polyline(stroke, palette::path, 3.0f);
  const auto& joints = view.joints;
  if (joints.empty()) return;
  double reach = 0.0;
  for (std::size_t i = 1; i < joints.size(); ++i) reach += (joints[i] - joints[i - 1]).norm();
  const double thickness = 0.04 * reach / 2.6;  // the lab's arm (reach 2.6): 4 cm bones
  for (std::size_t i = 1; i < joints.size(); ++i) {
    out.add_bone_box(joints[i - 1], joints[i], thickness, palette::bone);
  }
  for (std::size_t i = 0; i + 1 < joints.size(); ++i) {
    out.add_sphere(joints[i], 0.75 * thickness, palette::joint);
  }
  out.add_sphere(joints.back(), 0.6 * thickness, palette::end_effector);
  out.add_point(joints.back(), palette::end_effector, 9.0f);  // the pen, and the drag handle
  if (view.unreachable_target) {
    out.add_line(joints.back(), *view.unreachable_target, palette::unreachable, 2.0f);
    out.add_point(*view.unreachable_target, palette::unreachable, 14.0f);
  }
}

void IkScene::describe(DrawList& out) const {
  std::optional<Vec3> unreachable;
  if (last_ && !last_->result.reachable) unreachable = last_->target;
  describe_arm_drawing(
      out, {pose_.global_positions, trajectory_.targets, trajectory_.pen_down, path_, unreachable});
}

Eigen::AlignedBox3d IkScene::focus_bounds() const {
  Eigen::AlignedBox3d box;
  for (const Vec3& t : trajectory_.targets) box.extend(t);
  for (const Vec3& p : pose_.global_positions) box.extend(p);
  box.extend(chain_.root_position());
  return box;
}

}  // namespace animkit
