#include "animkit/kinematics/fabrik_tree.h"

#include <algorithm>
#include <cmath>

#include "tree_ik_common.h"

namespace animkit {

namespace {

detail::TreeLoopSettings loop_settings(const FabrikTreeSettings& settings) {
  return {settings.max_iterations, settings.tolerance, settings.angular_tolerance};
}

class FabrikTreeIteration final : public detail::TreeIteration {
 public:
  FabrikTreeIteration(const Skeleton& skeleton, const TreeIkProblem& problem,
                      FabrikTreeWorkspace& workspace)
      : skeleton_(skeleton), problem_(problem), ws_(workspace) {}

  void iterate(SkeletonPose& pose) override {
    backward_pass(pose);
    forward_pass(pose);
  }

 private:
  // A&L 2011, Alg. 1's backward loop, per branch: joint i goes to
  //   p_i' = p_{i+1}' + len_{i+1} (p_i - p_{i+1}') / |p_i - p_{i+1}'|
  // and a joint asked by several branches (a sub-base) or also carrying an effector goes to
  // the weighted centroid of the asked positions (A&L 2011, section 5). Roots are not moved,
  // so nothing is asked of them.
  void backward_pass(const SkeletonPose& pose) {
    const auto& p = pose.global_positions;
    auto& desired = ws_.desired;
    auto& weight = ws_.desired_weight;
    std::fill(desired.begin(), desired.end(), Vec3::Zero());
    std::fill(weight.begin(), weight.end(), 0.0);
    for (const Effector& e : problem_.effectors) {
      const auto j = static_cast<std::size_t>(e.joint);
      desired[j] = e.weight * e.position;
      weight[j] = e.weight;
    }
    const auto& subtree_weight = ws_.scratch.subtree_weight;
    // Children before parents: a joint's sum is complete when it is reached.
    for (int i = skeleton_.joint_count() - 1; i >= 0; --i) {
      const auto j = static_cast<std::size_t>(i);
      const int parent = skeleton_.parents()[j];
      if (subtree_weight[j] <= 0.0 || parent < 0) continue;
      desired[j] /= weight[j];
      const auto up = static_cast<std::size_t>(parent);
      const double length = pose.local_translations[j].norm();
      Vec3 toward = p[up] - desired[j];
      // The joint's current bone gives the direction when the line is undefined.
      if (toward.squaredNorm() == 0.0) toward = p[up] - p[j];
      const double norm = toward.norm();
      const Vec3 asked = norm > 0.0 ? Vec3(desired[j] + toward * (length / norm)) : desired[j];
      desired[up] += subtree_weight[j] * asked;
      weight[up] += subtree_weight[j];
    }
  }

  // A&L 2011, Alg. 1's forward loop as rotations: p_{i+1}' = p_i' + len (p_{i+1}' - p_i') /
  // |..| is the child placed by turning joint i by the shortest arc onto that direction; with
  // several children, by the weighted best-fit rotation. The limit is applied to that turn
  // before the children are placed (this loop is forward kinematics with the rotations
  // chosen on the way).
  void forward_pass(SkeletonPose& pose) {
    const auto& scratch = ws_.scratch;
    const auto& begin = skeleton_.child_begin();
    const auto& children = skeleton_.child_list();
    for (int i = 0; i < skeleton_.joint_count(); ++i) {
      const auto j = static_cast<std::size_t>(i);
      const int parent = skeleton_.parents()[j];
      const Quat above = detail::parent_rotation(skeleton_, pose, i);
      if (parent < 0) {
        pose.global_positions[j] = pose.local_translations[j];
      } else {
        const auto up = static_cast<std::size_t>(parent);
        pose.global_positions[j] = pose.global_positions[up] + above * pose.local_translations[j];
      }
      Quat& local = pose.local_rotations[j];
      if (scratch.below_weight[j] > 0.0) {
        const Quat current = above * local;
        detail::BestFitRotation fit;
        for (int k = begin[j]; k < begin[j + 1]; ++k) {
          const auto c = static_cast<std::size_t>(children[static_cast<std::size_t>(k)]);
          if (scratch.subtree_weight[c] <= 0.0) continue;
          const Vec3 to = ws_.desired[c] - pose.global_positions[j];
          const double length = pose.local_translations[c].norm();
          const double norm = to.norm();
          if (norm == 0.0) continue;
          fit.add(current * pose.local_translations[c], to * (length / norm),
                  scratch.subtree_weight[c]);
        }
        local = detail::limited_local(skeleton_, problem_.limits, i,
                                      above.conjugate() * fit.rotation() * current);
      } else if (const int e = scratch.effector_of[j]; e >= 0) {
        const auto& orientation = problem_.effectors[static_cast<std::size_t>(e)].orientation;
        if (orientation) {
          local = detail::limited_local(skeleton_, problem_.limits, i,
                                        above.conjugate() * *orientation);
        }
      }
      pose.global_rotations[j] = above * local;
    }
  }

  const Skeleton& skeleton_;
  const TreeIkProblem& problem_;
  FabrikTreeWorkspace& ws_;
};

}  // namespace

std::optional<Error> FabrikTreeSettings::validate() const {
  return detail::validate_tree_loop_settings(loop_settings(*this));
}

void FabrikTreeWorkspace::resize(const Skeleton& skeleton) {
  const int n = skeleton.joint_count();
  scratch.resize(n);
  desired.resize(static_cast<std::size_t>(n));
  desired_weight.resize(static_cast<std::size_t>(n));
}

Result<TreeIkResult> solve_fabrik_tree(const Skeleton& skeleton, const TreeIkProblem& problem,
                                       const FabrikTreeSettings& settings,
                                       FabrikTreeWorkspace& workspace, SkeletonPose& pose) {
  const detail::TreeLoopSettings loop = loop_settings(settings);
  if (auto error = detail::check_tree_ik(skeleton, problem, pose, loop))
    return fail(error->message);
  workspace.resize(skeleton);
  FabrikTreeIteration iteration(skeleton, problem, workspace);
  return detail::run_tree_ik(skeleton, problem, loop, workspace.scratch, pose, iteration);
}

}  // namespace animkit
