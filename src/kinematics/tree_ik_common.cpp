#include "tree_ik_common.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <string>

#include "animkit/core/quaternion_math.h"
#include "animkit/core/validation.h"

namespace animkit::detail {

namespace {

// An iteration that changes the score (below) by less than this fraction makes no progress;
// after kStallIterations of them in a row the solve bends its joints once (up to kMaxKicks
// times) and then stops.
constexpr double kStallRatio = 1e-6;
constexpr int kStallIterations = 3;
constexpr int kMaxKicks = 10;

// Both errors against their tolerances in one number: converged when <= 1.
double score(const TreeIkErrors& errors, const TreeLoopSettings& settings) {
  return std::max(errors.position / settings.tolerance,
                  errors.orientation / settings.angular_tolerance);
}

void project_into_limits(const Skeleton& skeleton, std::span<const JointLimit> limits,
                         SkeletonPose& pose) {
  for (int j = 0; j < skeleton.joint_count(); ++j) {
    auto& local = pose.local_rotations[static_cast<std::size_t>(j)];
    local = limited_local(skeleton, limits, j, local);
  }
  skeleton_forward_kinematics(skeleton, pose);
}

}  // namespace

void kick(const Skeleton& skeleton, std::span<const JointLimit> limits,
          const TreeIkScratch& scratch, SkeletonPose& pose) {
  const auto& begin = skeleton.child_begin();
  for (int j = 0; j < skeleton.joint_count(); ++j) {
    const auto uj = static_cast<std::size_t>(j);
    if (scratch.below_weight[uj] <= 0.0) continue;
    for (int k = begin[uj]; k < begin[uj + 1]; ++k) {
      const auto c = static_cast<std::size_t>(skeleton.child_list()[static_cast<std::size_t>(k)]);
      const Vec3& bone = pose.local_translations[c];
      if (scratch.subtree_weight[c] <= 0.0 || bone.squaredNorm() == 0.0) continue;
      const Quat bend(Eigen::AngleAxisd(kKickAngle, perpendicular_axis(bone)));
      pose.local_rotations[uj] =
          limited_local(skeleton, limits, j, pose.local_rotations[uj] * bend);
      break;
    }
  }
  skeleton_forward_kinematics(skeleton, pose);
}

std::optional<Error> validate_tree_loop_settings(const TreeLoopSettings& settings) {
  if (settings.max_iterations < 1) {
    return Error{"max iterations must be at least 1, got " +
                 std::to_string(settings.max_iterations)};
  }
  // isfinite first: an ordered comparison with NaN raises FE_INVALID, which the tests trap.
  if (!std::isfinite(settings.tolerance) || settings.tolerance <= 0.0) {
    return Error{"tolerance must be a positive finite number, got " +
                 format_number(settings.tolerance)};
  }
  if (!std::isfinite(settings.angular_tolerance) || settings.angular_tolerance <= 0.0) {
    return Error{"angular tolerance must be a positive finite number, got " +
                 format_number(settings.angular_tolerance)};
  }
  return std::nullopt;
}

std::optional<Error> check_tree_ik(const Skeleton& skeleton, const TreeIkProblem& problem,
                                   const SkeletonPose& pose, const TreeLoopSettings& settings) {
  if (auto error = validate_tree_ik(skeleton, problem, pose)) return error;
  return validate_tree_loop_settings(settings);
}

void index_effectors(const Skeleton& skeleton, std::span<const Effector> effectors,
                     TreeIkScratch& scratch) {
  std::fill(scratch.effector_of.begin(), scratch.effector_of.end(), -1);
  std::fill(scratch.subtree_weight.begin(), scratch.subtree_weight.end(), 0.0);
  std::fill(scratch.below_weight.begin(), scratch.below_weight.end(), 0.0);
  for (std::size_t e = 0; e < effectors.size(); ++e) {
    const auto j = static_cast<std::size_t>(effectors[e].joint);
    scratch.effector_of[j] = static_cast<int>(e);
    scratch.subtree_weight[j] = effectors[e].weight;
  }
  // Children before parents: each joint's total is complete when it is added to its parent.
  for (int j = skeleton.joint_count() - 1; j >= 0; --j) {
    const int p = skeleton.parents()[static_cast<std::size_t>(j)];
    if (p < 0) continue;
    const auto up = static_cast<std::size_t>(p);
    scratch.subtree_weight[up] += scratch.subtree_weight[static_cast<std::size_t>(j)];
    scratch.below_weight[up] += scratch.subtree_weight[static_cast<std::size_t>(j)];
  }
}

Quat limited_local(const Skeleton& skeleton, std::span<const JointLimit> limits, int joint,
                   const Quat& local) {
  if (limits.empty()) return local.normalized();
  const auto j = static_cast<std::size_t>(joint);
  const Quat& rest = skeleton.rest_rotations()[j];
  return (rest * constrain(limits[j], (rest.conjugate() * local).normalized())).normalized();
}

void BestFitRotation::add(const Vec3& from, const Vec3& to, double weight) {
  if (from.squaredNorm() == 0.0 || to.squaredNorm() == 0.0) return;
  if (count_ == 0) {
    first_from_ = from;
    first_to_ = to;
  }
  h_.noalias() += weight * from * to.transpose();
  ++count_;
}

Quat BestFitRotation::rotation() const {
  if (count_ == 0) return Quat::Identity();
  if (count_ == 1) return shortest_arc(first_from_, first_to_);
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(h_, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Vec3& s = svd.singularValues();
  const Eigen::Matrix3d& u = svd.matrixU();
  const Eigen::Matrix3d& v = svd.matrixV();
  // Rank one: u_k all along U's first column, v_k along V's (signs as H pairs them).
  if (s(1) <= 1e-12 * s(0)) return shortest_arc(u.col(0), v.col(0));
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (v * u.transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  return Quat(Eigen::Matrix3d(v * d * u.transpose())).normalized();
}

Quat BestFitRotation::rotation_about(const Vec3& axis) const {
  if (count_ == 0) return Quat::Identity();
  const Vec3 cross(h_(1, 2) - h_(2, 1), h_(2, 0) - h_(0, 2), h_(0, 1) - h_(1, 0));
  const double sine = axis.dot(cross);
  const double cosine = h_.trace() - axis.dot(h_ * axis);
  if (sine == 0.0 && cosine >= 0.0) return Quat::Identity();
  return Quat(Eigen::AngleAxisd(std::atan2(sine, cosine), axis));
}

Quat best_turn(const BestFitRotation& fit, const Skeleton& skeleton,
               std::span<const JointLimit> limits, int joint, const Quat& above) {
  if (!is_hinge(limits, joint)) return fit.rotation();
  const auto j = static_cast<std::size_t>(joint);
  const Vec3 axis = above * (skeleton.rest_rotations()[j] * std::get<HingeLimit>(limits[j]).axis);
  return fit.rotation_about(axis.normalized());
}

TreeIkResult run_tree_ik(const Skeleton& skeleton, const TreeIkProblem& problem,
                         const TreeLoopSettings& settings, TreeIkScratch& scratch,
                         SkeletonPose& pose, TreeIteration& iteration) {
  index_effectors(skeleton, problem.effectors, scratch);
  project_into_limits(skeleton, problem.limits, pose);
  TreeIkResult result;
  result.reachable = tree_ik_reachable(skeleton, pose, problem.effectors);
  double current = score(tree_ik_errors(pose, problem.effectors), settings);
  double best = current;
  scratch.best_local_rotations = pose.local_rotations;  // same size: no allocation
  int stalled = 0, kicks = 0;
  while (current > 1.0 && result.iterations < settings.max_iterations) {
    iteration.iterate(pose);
    ++result.iterations;
    const double next = score(tree_ik_errors(pose, problem.effectors), settings);
    if (next < best) {
      best = next;
      scratch.best_local_rotations = pose.local_rotations;
    }
    // Only an iteration that changes nothing counts: with limits the score may rise for a few
    // iterations on the way to a solution.
    stalled = std::abs(next - current) <= kStallRatio * current ? stalled + 1 : 0;
    current = next;
    if (stalled >= kStallIterations && current > 1.0) {
      if (kicks == kMaxKicks) break;
      ++kicks;
      stalled = 0;
      kick(skeleton, problem.limits, scratch, pose);
      current = score(tree_ik_errors(pose, problem.effectors), settings);
    }
  }
  if (current > best) {
    pose.local_rotations = scratch.best_local_rotations;
    skeleton_forward_kinematics(skeleton, pose);
  }
  const TreeIkErrors errors = tree_ik_errors(pose, problem.effectors);
  result.error = errors.position;
  result.orientation_error = errors.orientation;
  result.converged = score(errors, settings) <= 1.0;
  return result;
}

}  // namespace animkit::detail
