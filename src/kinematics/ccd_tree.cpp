#include "animkit/kinematics/ccd_tree.h"

#include "tree_ik_common.h"

namespace animkit {

namespace {

detail::TreeLoopSettings loop_settings(const CcdTreeSettings& settings) {
  return {settings.max_iterations, settings.tolerance, settings.angular_tolerance};
}

// Whether `joint` lies strictly below `ancestor` (parents have smaller indices, so the walk up
// stops as soon as it passes the ancestor's index).
bool strictly_below(const Skeleton& skeleton, int joint, int ancestor) {
  while (joint > ancestor) joint = skeleton.parents()[static_cast<std::size_t>(joint)];
  return joint == ancestor;
}

class CcdTreeIteration final : public detail::TreeIteration {
 public:
  CcdTreeIteration(const Skeleton& skeleton, const TreeIkProblem& problem,
                   CcdTreeWorkspace& workspace)
      : skeleton_(skeleton), problem_(problem), ws_(workspace) {}

  // One sweep, children before parents (docs/how-it-works.md, "from the joint nearest the end
  // effector back to the root", with every effector below the joint taken at once).
  void iterate(SkeletonPose& pose) override {
    const auto& scratch = ws_.scratch;
    for (int i = skeleton_.joint_count() - 1; i >= 0; --i) {
      const auto j = static_cast<std::size_t>(i);
      const Quat above = detail::parent_rotation(skeleton_, pose, i);
      Quat& local = pose.local_rotations[j];
      if (scratch.below_weight[j] > 0.0) {
        local =
            detail::limited_local(skeleton_, problem_.limits, i,
                                  above.conjugate() * turn_toward_targets(pose, i) * above * local);
      } else if (const int e = scratch.effector_of[j]; e >= 0) {
        const auto& orientation = problem_.effectors[static_cast<std::size_t>(e)].orientation;
        if (!orientation) continue;
        local =
            detail::limited_local(skeleton_, problem_.limits, i, above.conjugate() * *orientation);
      } else {
        continue;
      }
      update_subtree(pose, i);
    }
  }

 private:
  // The world rotation about joint i that best takes its effectors onto their targets:
  // pairs (e_k - p, t_k - p) weighted by w_k (see BestFitRotation).
  Quat turn_toward_targets(const SkeletonPose& pose, int i) const {
    const Vec3& at = pose.global_positions[static_cast<std::size_t>(i)];
    detail::BestFitRotation fit;
    for (const Effector& e : problem_.effectors) {
      if (!strictly_below(skeleton_, e.joint, i)) continue;
      fit.add(pose.global_positions[static_cast<std::size_t>(e.joint)] - at, e.position - at,
              e.weight);
    }
    return detail::best_turn(fit, skeleton_, problem_.limits, i,
                             detail::parent_rotation(skeleton_, pose, i));
  }

  // Forward kinematics of joint i's subtree after its local rotation changed. Its descendants
  // follow it in index order; marks flag them (a joint is in the subtree when its parent is).
  void update_subtree(SkeletonPose& pose, int i) {
    auto& marks = ws_.scratch.marks;
    const auto j = static_cast<std::size_t>(i);
    pose.global_rotations[j] =
        detail::parent_rotation(skeleton_, pose, i) * pose.local_rotations[j];
    marks[j] = 1;
    for (int k = i + 1; k < skeleton_.joint_count(); ++k) {
      const auto uk = static_cast<std::size_t>(k);
      const int parent = skeleton_.parents()[uk];
      marks[uk] = parent >= i && marks[static_cast<std::size_t>(parent)];
      if (!marks[uk]) continue;
      const auto up = static_cast<std::size_t>(parent);
      pose.global_rotations[uk] = pose.global_rotations[up] * pose.local_rotations[uk];
      pose.global_positions[uk] =
          pose.global_positions[up] + pose.global_rotations[up] * pose.local_translations[uk];
    }
  }

  const Skeleton& skeleton_;
  const TreeIkProblem& problem_;
  CcdTreeWorkspace& ws_;
};

}  // namespace

std::optional<Error> CcdTreeSettings::validate() const {
  return detail::validate_tree_loop_settings(loop_settings(*this));
}

void CcdTreeWorkspace::resize(const Skeleton& skeleton) {
  scratch.resize(skeleton.joint_count());
}

Result<TreeIkResult> solve_ccd_tree(const Skeleton& skeleton, const TreeIkProblem& problem,
                                    const CcdTreeSettings& settings, CcdTreeWorkspace& workspace,
                                    SkeletonPose& pose) {
  const detail::TreeLoopSettings loop = loop_settings(settings);
  if (auto error = detail::check_tree_ik(skeleton, problem, pose, loop))
    return fail(error->message);
  workspace.resize(skeleton);
  CcdTreeIteration iteration(skeleton, problem, workspace);
  return detail::run_tree_ik(skeleton, problem, loop, workspace.scratch, pose, iteration);
}

}  // namespace animkit
