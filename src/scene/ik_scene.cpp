#include "animkit/scene/ik_scene.h"

#include <cassert>
#include <chrono>
#include <string>

#include "animkit/core/validation.h"

namespace animkit {

namespace {
std::optional<Error> check_targets(const std::vector<Vec3>& targets) {
  if (targets.empty()) return Error{"the target list is empty"};
  for (std::size_t i = 0; i < targets.size(); ++i) {
    if (!is_finite(targets[i])) {
      return Error{"target " + std::to_string(i) + " has a non-finite coordinate " +
                   to_string(targets[i])};
    }
  }
  return std::nullopt;
}
}  // namespace

IkScene::IkScene(Chain chain, std::vector<Vec3> targets, const IkSceneOptions& options)
    : chain_(std::move(chain)),
      pose_(rest_pose(chain_)),
      targets_(std::move(targets)),
      options_(options) {}

Result<IkScene> IkScene::create(const ChainDesc& desc, std::vector<Vec3> targets,
                                const IkSceneOptions& options) {
  if (auto error = options.ik.validate()) return fail(error->message);
  if (auto error = check_targets(targets)) return fail(error->message);
  auto chain = build_chain(desc);
  if (!chain) return fail(chain.error().message);
  return IkScene(std::move(*chain), std::move(targets), options);
}

void IkScene::reset() {
  pose_ = rest_pose(chain_);
  path_.clear();
  next_ = 0;
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
  }
  solve(targets_[next_]);
  path_.push_back(pose_.end_effector());
  next_ = (next_ + 1) % static_cast<int>(targets_.size());
  return *last_;
}

Result<IkSolveReadout> IkScene::follow(const Vec3& target) {
  if (!is_finite(target)) return fail("target has a non-finite coordinate " + to_string(target));
  return solve(target);
}

Result<void> IkScene::set_targets(std::vector<Vec3> targets) {
  if (auto error = check_targets(targets)) return fail(error->message);
  targets_ = std::move(targets);
  reset();
  return {};
}

void describe_arm_drawing(DrawList& out, std::span<const Vec3> joints,
                          std::span<const Vec3> targets, std::span<const Vec3> path,
                          const std::optional<Vec3>& unreachable_target) {
  // The grid sits just below the drawing plane y = 0 so the path never fights it for depth.
  out.add_ground_grid(-0.002, 12, 0.25, 0.5);
  for (const Vec3& t : targets) out.add_point(t, palette::target, 5.0f);
  for (std::size_t i = 1; i < path.size(); ++i)
    out.add_line(path[i - 1], path[i], palette::path, 3.0f);
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
  if (unreachable_target) {
    out.add_line(joints.back(), *unreachable_target, palette::unreachable, 2.0f);
    out.add_point(*unreachable_target, palette::unreachable, 14.0f);
  }
}

void IkScene::describe(DrawList& out) const {
  std::optional<Vec3> unreachable;
  if (last_ && !last_->result.reachable) unreachable = last_->target;
  describe_arm_drawing(out, pose_.global_positions, targets_, path_, unreachable);
}

Eigen::AlignedBox3d IkScene::focus_bounds() const {
  Eigen::AlignedBox3d box;
  for (const Vec3& t : targets_) box.extend(t);
  for (const Vec3& p : pose_.global_positions) box.extend(p);
  box.extend(chain_.root_position());
  return box;
}

}  // namespace animkit
