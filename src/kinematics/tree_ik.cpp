#include "animkit/kinematics/tree_ik.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "animkit/core/validation.h"
#include "animkit/kinematics/ik_types.h"

namespace animkit {

namespace {

std::string effector_name(std::size_t e) {
  return "effector " + std::to_string(e);
}

}  // namespace

std::optional<Error> validate_tree_ik(const Skeleton& skeleton, const TreeIkProblem& problem,
                                      const SkeletonPose& pose) {
  const auto n = static_cast<std::size_t>(skeleton.joint_count());
  if (pose.local_rotations.size() != n || pose.local_translations.size() != n ||
      pose.global_rotations.size() != n || pose.global_positions.size() != n) {
    return Error{"the pose has " + std::to_string(pose.local_rotations.size()) +
                 " joints, the skeleton " + std::to_string(n)};
  }
  if (problem.effectors.empty()) return Error{"IK needs at least one effector"};
  // Solvers run this on every call and must not allocate then: names are built, and repeated
  // joints searched for (a quadratic scan over a handful of effectors), only on the way to an
  // error.
  for (std::size_t e = 0; e < problem.effectors.size(); ++e) {
    const Effector& effector = problem.effectors[e];
    if (effector.joint < 0 || static_cast<std::size_t>(effector.joint) >= n) {
      return Error{effector_name(e) + " names joint " + std::to_string(effector.joint) +
                   ", the skeleton has joints 0 to " + std::to_string(n - 1)};
    }
    const auto joint_index = static_cast<std::size_t>(effector.joint);
    const auto name = [&] { return effector_name(e) + " (" + skeleton.names()[joint_index] + ")"; };
    if (skeleton.parents()[joint_index] < 0) {
      return Error{effector_name(e) + " is on the root " + skeleton.names()[joint_index] +
                   ", which IK never moves"};
    }
    for (std::size_t f = 0; f < e; ++f) {
      if (problem.effectors[f].joint == effector.joint) {
        return Error{effector_name(e) + ": joint " + skeleton.names()[joint_index] +
                     " has two effectors"};
      }
    }
    if (!is_finite(effector.position) ||
        effector.position.cwiseAbs().maxCoeff() > kMaxTargetCoordinate)
      return Error{name() + ": the target position must be finite and within 1e9"};
    if (effector.orientation && !(is_finite(*effector.orientation) &&
                                  std::abs(effector.orientation->norm() - 1.0) <= 1e-6)) {
      return Error{name() + ": the target orientation must be a unit quaternion"};
    }
    if (!std::isfinite(effector.weight) || effector.weight <= 0.0) {
      return Error{name() + ": the weight must be > 0, got " + format_number(effector.weight)};
    }
  }
  if (!problem.limits.empty()) {
    if (problem.limits.size() != n) {
      return Error{"joint limits: " + std::to_string(problem.limits.size()) +
                   " given, the skeleton has " + std::to_string(n) + " joints"};
    }
    for (std::size_t j = 0; j < n; ++j) {
      if (auto error = validate(problem.limits[j]))
        return Error{"joint " + skeleton.names()[j] + "'s limit: " + error->message};
    }
  }
  return std::nullopt;
}

TreeIkErrors tree_ik_errors(const SkeletonPose& pose, std::span<const Effector> effectors) {
  TreeIkErrors errors;
  for (const Effector& e : effectors) {
    const auto j = static_cast<std::size_t>(e.joint);
    errors.position = std::max(errors.position, (pose.global_positions[j] - e.position).norm());
    if (e.orientation) {
      errors.orientation =
          std::max(errors.orientation, pose.global_rotations[j].angularDistance(*e.orientation));
    }
  }
  return errors;
}

bool tree_ik_reachable(const Skeleton& skeleton, const SkeletonPose& pose,
                       std::span<const Effector> effectors) {
  for (const Effector& e : effectors) {
    // Up to the root: the bones between it and the effector, as the pose has them.
    double reach = 0.0;
    int j = e.joint;
    while (skeleton.parents()[static_cast<std::size_t>(j)] >= 0) {
      reach += pose.local_translations[static_cast<std::size_t>(j)].norm();
      j = skeleton.parents()[static_cast<std::size_t>(j)];
    }
    if ((e.position - pose.global_positions[static_cast<std::size_t>(j)]).norm() > reach)
      return false;
  }
  return true;
}

void TreeIkScratch::resize(int joint_count) {
  const auto n = static_cast<std::size_t>(joint_count);
  subtree_weight.resize(n);
  below_weight.resize(n);
  effector_of.resize(n);
  best_local_rotations.resize(n);
  marks.resize(n);
}

bool TreeIkScratch::fits(int joint_count) const {
  const auto n = static_cast<std::size_t>(joint_count);
  return subtree_weight.size() == n && below_weight.size() == n && effector_of.size() == n &&
         best_local_rotations.size() == n && marks.size() == n;
}

}  // namespace animkit
