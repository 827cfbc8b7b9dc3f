// GCC 12's own AVX-512 intrinsics trip -Wuninitialized when Eigen's dense decompositions (the
// DLS finish's workspace) are inlined with -march=native at -O1: a false positive in the
// compiler's headers (see dls_tree.cpp), silenced for this file only.
#pragma GCC diagnostic ignored "-Wuninitialized"

#include "animkit/kinematics/fabrik_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <variant>

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
      : skeleton_(skeleton), problem_(problem), ws_(workspace) {
    // marks[j]: a hinge at j or below it (children after parents, so each is complete in time).
    auto& marks = ws_.scratch.marks;
    std::fill(marks.begin(), marks.end(), 0);
    for (int j = skeleton.joint_count() - 1; j >= 0; --j) {
      const auto uj = static_cast<std::size_t>(j);
      marks[uj] = static_cast<char>(marks[uj] | detail::is_hinge(problem.limits, j));
      const int parent = skeleton.parents()[uj];
      if (parent >= 0) marks[static_cast<std::size_t>(parent)] |= marks[uj];
    }
  }

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
      if (detail::is_hinge(problem_.limits, i)) toward = hinge_toward(pose, i, toward);
      const double norm = toward.norm();
      const Vec3 asked = norm > 0.0 ? Vec3(desired[j] + toward * (length / norm)) : desired[j];
      desired[up] += subtree_weight[j] * asked;
      weight[up] += subtree_weight[j];
    }
  }

  // Constrained FABRIK's backward pass (Aristidou & Lasenby 2011, section 4.1, as caliko does
  // it for hinges): the bone from the hinge `joint`'s parent, asked along `toward` (from the
  // joint's asked position toward the parent), is moved into the hinge's plane and its angle to
  // the bone below clamped to the hinge's range, so that the parent is asked where the hinge
  // can reach from. The plane is the one perpendicular to the hinge's current world axis, made
  // perpendicular to the asked bone below. Only for a hinge with one branch of effectors below.
  Vec3 hinge_toward(const SkeletonPose& pose, int joint, const Vec3& toward) const {
    const auto j = static_cast<std::size_t>(joint);
    const auto& begin = skeleton_.child_begin();
    int below = -1;
    for (int k = begin[j]; k < begin[j + 1]; ++k) {
      const int c = skeleton_.child_list()[static_cast<std::size_t>(k)];
      if (ws_.scratch.subtree_weight[static_cast<std::size_t>(c)] <= 0.0) continue;
      if (below >= 0) return toward;  // a sub-base: several bones below
      below = c;
    }
    if (below < 0) return toward;
    const auto g = static_cast<std::size_t>(below);
    const HingeLimit& hinge = std::get<HingeLimit>(problem_.limits[j]);
    const Quat& rest = skeleton_.rest_rotations()[j];
    // Signed angle from u to v about the unit a, both projected on a's plane.
    auto angle_about = [](const Vec3& u, const Vec3& v, const Vec3& a) {
      const Vec3 pu = u - a * a.dot(u), pv = v - a * a.dot(v);
      return std::atan2(a.dot(pu.cross(pv)), pu.dot(pv));
    };
    const Vec3 shin = ws_.desired[g] - ws_.desired[j];
    const Vec3 thigh_rest = rest.conjugate() * pose.local_translations[j];  // rest frame
    if (shin.squaredNorm() == 0.0 || thigh_rest.squaredNorm() == 0.0) return toward;
    const Vec3 down = shin.normalized();
    Vec3 axis = detail::parent_rotation(skeleton_, pose, joint) * (rest * hinge.axis);
    axis -= down * down.dot(axis);
    if (axis.squaredNorm() < 1e-18) return toward;
    axis.normalize();
    // At hinge angle theta the bone below is turned by theta about the axis from where it is at
    // rest relative to the bone above: their angle about the axis is rest_angle + theta.
    const double rest_angle = angle_about(thigh_rest, pose.local_translations[g], hinge.axis);
    const double angle = angle_about(-toward, shin, axis);
    double theta = angle - rest_angle;
    theta -= 2.0 * std::numbers::pi * std::round(theta / (2.0 * std::numbers::pi));
    if (theta < hinge.min_angle || theta > hinge.max_angle) {
      auto gap = [&](double end) {
        const double d = theta - end;
        return std::abs(d - 2.0 * std::numbers::pi * std::round(d / (2.0 * std::numbers::pi)));
      };
      theta = gap(hinge.min_angle) <= gap(hinge.max_angle) ? hinge.min_angle : hinge.max_angle;
    }
    // The bone above, pointing down to the joint: the bone below turned back by the angle, plus
    // its rest component along the axis.
    const Vec3 unit_rest = thigh_rest.normalized();
    const double along = unit_rest.dot(hinge.axis);
    const double across = std::sqrt(std::max(0.0, 1.0 - along * along));
    const Vec3 thigh =
        across * (Eigen::AngleAxisd(-(rest_angle + theta), axis) * down) + along * axis;
    return -thigh * toward.norm();
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
        int aimed = -1;
        for (int k = begin[j]; k < begin[j + 1]; ++k) {
          const auto c = static_cast<std::size_t>(children[static_cast<std::size_t>(k)]);
          if (scratch.subtree_weight[c] <= 0.0) continue;
          const Vec3 to = ws_.desired[c] - pose.global_positions[j];
          const double length = pose.local_translations[c].norm();
          const double norm = to.norm();
          if (norm == 0.0 || length == 0.0) continue;  // no direction to aim
          fit.add(current * pose.local_translations[c], to * (length / norm),
                  scratch.subtree_weight[c]);
          aimed = static_cast<int>(c);
        }
        Quat turned = detail::best_turn(fit, skeleton_, problem_.limits, i, above) * current;
        if (fit.count() == 1 && !detail::is_hinge(problem_.limits, i))
          turned = twist_toward_grandchildren(pose, i, aimed, above, turned);
        local = detail::limited_local(skeleton_, problem_.limits, i, above.conjugate() * turned);
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

  // A joint aiming one child's bone has one degree of freedom left, the twist about that bone,
  // which moves no child but decides where the grandchildren can go. Without limits it is the
  // weighted least-squares rotation (the child keeping its local rotation) in the plane
  // perpendicular to the bone axis a,
  //   angle = atan2(sum_g w_g a . (u_g x v_g), sum_g w_g u_g . v_g),
  // with u_g, v_g the grandchild's current and asked offsets from the joint projected on that
  // plane. With limits that angle and seven more, an eighth of a turn apart,
  // are each tried: the joint turned and limited, the child aimed and limited as the pass
  // will do it, and the twist whose grandchildren land nearest their asked positions wins.
  // Otherwise a hinge below stays in whatever plane the shortest arcs leave it, bending the
  // wrong way or not at all, and targets off that plane are never reached.
  Quat twist_toward_grandchildren(const SkeletonPose& pose, int joint, int child, const Quat& above,
                                  const Quat& rotation) const {
    const auto j = static_cast<std::size_t>(joint);
    const auto c = static_cast<std::size_t>(child);
    const Vec3 bone = rotation * pose.local_translations[c];
    const auto& begin = skeleton_.child_begin();
    if (bone.squaredNorm() == 0.0 || begin[c] == begin[c + 1]) return rotation;
    const Vec3 axis = bone.normalized();
    const Vec3& at = pose.global_positions[j];
    const Quat child_rotation = rotation * pose.local_rotations[c];
    double sine = 0.0, cosine = 0.0;
    for (int k = begin[c]; k < begin[c + 1]; ++k) {
      const auto g = static_cast<std::size_t>(skeleton_.child_list()[static_cast<std::size_t>(k)]);
      const double w = ws_.scratch.subtree_weight[g];
      if (w <= 0.0) continue;
      Vec3 u = bone + child_rotation * pose.local_translations[g];
      Vec3 v = ws_.desired[g] - at;
      u -= axis * axis.dot(u);
      v -= axis * axis.dot(v);
      sine += w * axis.dot(u.cross(v));
      cosine += w * u.dot(v);
    }
    const Quat free_best = detail::about_axis_toward(sine, cosine, axis) * rotation;
    if (problem_.limits.empty()) return free_best;
    const double angle = sine == 0.0 && cosine >= 0.0 ? 0.0 : std::atan2(sine, cosine);
    // When neither the joint nor the child meets its limit at the free optimum, the search could
    // only tie for these grandchildren: take it and spare the other seven candidates. Not with a
    // hinge at the child or below: a hinge turns about its axis only, so the twist decides where
    // it can aim, further down than aim_error looks (with hinged knees and elbows, the CMU test's
    // passes reach 46% of the targets with the search here, 26% without).
    if (ws_.scratch.marks[c]) return search_twist(pose, joint, child, above, rotation, axis, angle);
    bool limited = false;
    aim_error(pose, joint, child, above, free_best, &limited);
    if (!limited) return free_best;
    return search_twist(pose, joint, child, above, rotation, axis, angle);
  }

  // The best of eight twists about `axis`, `angle` and seven more an eighth of a turn apart.
  Quat search_twist(const SkeletonPose& pose, int joint, int child, const Quat& above,
                    const Quat& rotation, const Vec3& axis, double angle) const {
    constexpr int kCandidates = 8;
    Quat best = rotation;
    double best_error = std::numeric_limits<double>::infinity();
    for (int m = 0; m < kCandidates; ++m) {
      const double turn = angle + 2.0 * std::numbers::pi * m / kCandidates;
      const Quat candidate = Quat(Eigen::AngleAxisd(turn, axis)) * rotation;
      const double error = aim_error(pose, joint, child, above, candidate, nullptr);
      if (error < best_error) {
        best_error = error;
        best = candidate;
      }
    }
    return best;
  }

  // How far the child and grandchildren land from their asked positions (weighted squares)
  // when the joint takes world rotation `rotation` (then limited) and the child aims its
  // children as the forward pass will (best fit, then limited). Sets *limited (when given) to
  // whether either limit changed its rotation.
  double aim_error(const SkeletonPose& pose, int joint, int child, const Quat& above,
                   const Quat& rotation, bool* limited) const {
    const auto j = static_cast<std::size_t>(joint);
    const auto c = static_cast<std::size_t>(child);
    const auto& weight = ws_.scratch.subtree_weight;
    const Quat joint_local = above.conjugate() * rotation;
    const Quat joint_limited =
        detail::limited_local(skeleton_, problem_.limits, joint, joint_local);
    const Quat joint_rotation = above * joint_limited;
    const Vec3 at_child = pose.global_positions[j] + joint_rotation * pose.local_translations[c];
    const Quat current = joint_rotation * pose.local_rotations[c];
    const auto& begin = skeleton_.child_begin();
    detail::BestFitRotation fit;
    for (int k = begin[c]; k < begin[c + 1]; ++k) {
      const auto g = static_cast<std::size_t>(skeleton_.child_list()[static_cast<std::size_t>(k)]);
      if (weight[g] <= 0.0) continue;
      const Vec3 to = ws_.desired[g] - at_child;
      const double norm = to.norm();
      if (norm == 0.0) continue;
      fit.add(current * pose.local_translations[g], to * (pose.local_translations[g].norm() / norm),
              weight[g]);
    }
    const Quat turn = detail::best_turn(fit, skeleton_, problem_.limits, child, joint_rotation);
    const Quat child_local = joint_rotation.conjugate() * turn * current;
    const Quat child_limited =
        detail::limited_local(skeleton_, problem_.limits, child, child_local);
    const Quat child_rotation = joint_rotation * child_limited;
    if (limited != nullptr) {
      *limited = !detail::same_rotation(joint_local, joint_limited) ||
                 !detail::same_rotation(child_local, child_limited);
    }
    double error = weight[c] * (at_child - ws_.desired[c]).squaredNorm();
    for (int k = begin[c]; k < begin[c + 1]; ++k) {
      const auto g = static_cast<std::size_t>(skeleton_.child_list()[static_cast<std::size_t>(k)]);
      if (weight[g] <= 0.0) continue;
      const Vec3 placed = at_child + child_rotation * pose.local_translations[g];
      error += weight[g] * (placed - ws_.desired[g]).squaredNorm();
    }
    return error;
  }

  const Skeleton& skeleton_;
  const TreeIkProblem& problem_;
  FabrikTreeWorkspace& ws_;
};

// Both errors against the tolerances in one number: converged when <= 1.
double score(const TreeIkErrors& errors, const FabrikTreeSettings& settings) {
  return std::max(errors.position / settings.tolerance,
                  errors.orientation / settings.angular_tolerance);
}

// DLS from FABRIK's pose (FabrikTreeSettings::finish_with_dls); keeps whichever pose is better.
void finish_with_dls(const Skeleton& skeleton, const TreeIkProblem& problem,
                     const FabrikTreeSettings& settings, FabrikTreeWorkspace& workspace,
                     SkeletonPose& pose, TreeIkResult& result) {
  DlsSettings dls = settings.dls_finish;
  dls.tolerance = settings.tolerance;
  dls.angular_tolerance = settings.angular_tolerance;
  const double before = score({result.error, result.orientation_error}, settings);
  auto& fabrik_pose = workspace.scratch.best_local_rotations;
  fabrik_pose = pose.local_rotations;  // same size: no allocation
  const auto finished = solve_dls_tree(skeleton, problem, dls, workspace.dls, pose);
  // Inputs and settings were validated, so the solve cannot fail; stay with FABRIK's if it did.
  const bool better =
      finished && score({finished->error, finished->orientation_error}, settings) < before;
  if (!better) {
    pose.local_rotations = fabrik_pose;
    skeleton_forward_kinematics(skeleton, pose);
  } else {
    result.error = finished->error;
    result.orientation_error = finished->orientation_error;
    result.converged = finished->converged;
  }
  if (finished) result.finish_iterations = finished->iterations;
}

}  // namespace

std::optional<Error> FabrikTreeSettings::validate() const {
  if (auto error = detail::validate_tree_loop_settings(loop_settings(*this))) return error;
  if (!finish_with_dls) return std::nullopt;
  // The finish uses this solve's tolerances: validate the rest of its settings with them.
  DlsSettings dls = dls_finish;
  dls.tolerance = tolerance;
  dls.angular_tolerance = angular_tolerance;
  if (auto error = dls.validate()) return Error{"FABRIK's DLS finish: " + error->message};
  return std::nullopt;
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
  if (auto error = settings.validate()) return fail(error->message);
  workspace.resize(skeleton);
  // Sized whether or not the finish runs, so that a warm workspace never allocates for it.
  if (settings.finish_with_dls) workspace.dls.resize(skeleton, problem);
  FabrikTreeIteration iteration(skeleton, problem, workspace);
  TreeIkResult result =
      detail::run_tree_ik(skeleton, problem, loop, workspace.scratch, pose, iteration);
  if (settings.finish_with_dls && !result.converged && result.reachable)
    finish_with_dls(skeleton, problem, settings, workspace, pose, result);
  return result;
}

}  // namespace animkit
