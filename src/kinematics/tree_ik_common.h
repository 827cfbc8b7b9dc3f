#pragma once
// Private pieces the tree IK solvers share (FABRIK for trees, CCD over trees): input checks,
// effector bookkeeping, joint limits applied to a local rotation, the weighted best-fit
// rotation, and the iteration loop with its stopping rules.
#include <Eigen/Core>
#include <cmath>
#include <optional>
#include <span>

#include "animkit/core/result.h"
#include "animkit/kinematics/tree_ik.h"

namespace animkit::detail {

/// Settings every tree solver's loop reads (each solver's settings struct holds them).
struct TreeLoopSettings {
  int max_iterations = 100;
  double tolerance = 1e-4;
  double angular_tolerance = 1e-3;
};

/// "max iterations must be at least 1, got 0" and the like, or nothing.
std::optional<Error> validate_tree_loop_settings(const TreeLoopSettings& settings);

/// validate_tree_ik, then the settings; the first problem found.
std::optional<Error> check_tree_ik(const Skeleton& skeleton, const TreeIkProblem& problem,
                                   const SkeletonPose& pose, const TreeLoopSettings& settings);

/// Fills effector_of, subtree_weight and below_weight of `scratch` (sized for the skeleton).
void index_effectors(const Skeleton& skeleton, std::span<const Effector> effectors,
                     TreeIkScratch& scratch);

/// The local rotation `local` of `joint` moved inside its limit (applied relative to rest, as
/// tree_ik.h says), unit. Unchanged but normalized when `limits` is empty.
Quat limited_local(const Skeleton& skeleton, std::span<const JointLimit> limits, int joint,
                   const Quat& local);

/// Whether the unit quaternions a and b are one rotation up to rounding (q and -q are one).
inline bool same_rotation(const Quat& a, const Quat& b) {
  return std::abs(a.dot(b)) >= 1.0 - 1e-14;
}

// The rotation about the unit `axis` by atan2(sine, cosine), without the trigonometry (FABRIK's
// forward pass runs it for most joints): its quaternion (cos a/2, sin a/2 axis) is parallel to
// (1 + cos a, sin a) = (r + cosine, sine) / r, r = |(sine, cosine)|, and to
// (sin a, 1 - cos a); the first is accurate for cosine >= 0, the second otherwise.
inline Quat about_axis_toward(double sine, double cosine, const Vec3& axis) {
  const double r = std::sqrt(sine * sine + cosine * cosine);
  if (sine == 0.0 && cosine >= 0.0) return Quat::Identity();
  const double w = cosine >= 0.0 ? r + cosine : sine;
  const double s = cosine >= 0.0 ? sine : r - cosine;
  const double n = std::sqrt(w * w + s * s);
  const Vec3 v = axis * (s / n);
  return Quat(w / n, v.x(), v.y(), v.z());
}

/// The rotation R minimizing sum_k w_k |R u_k - v_k|^2 (Wahba's problem), accumulated pair by
/// pair. Solved as Kabsch does: with H = sum_k w_k u_k v_k^T = U S V^T,
///   R = V diag(1, 1, d) U^T,  d = sign(det(V U^T))  (a rotation, never a reflection).
/// With one pair, or when every u_k and every v_k lie on one line (H of rank one, where the
/// SVD's twist about that line is arbitrary), R is the shortest arc instead: the lab's CCD
/// rotation, and the least-turning of the optimal rotations.
class BestFitRotation {
 public:
  /// Adds a pair; pairs with a zero vector carry no direction and are skipped.
  void add(const Vec3& from, const Vec3& to, double weight);
  /// Identity when no pair was added.
  Quat rotation() const;
  /// The rotation about the unit `axis` minimizing the same sum: with c = sum_k w_k u_k x v_k
  /// (read off H's antisymmetric part) and the pairs' parts perpendicular to the axis,
  ///   angle = atan2(axis . c, tr(H) - axis^T H axis).
  /// A hinge's best turn; the twist part of the free best fit is not (it is nearest in angle,
  /// not in where the pairs land).
  Quat rotation_about(const Vec3& axis) const;
  /// How many pairs were added (pairs with a zero vector are not counted).
  int count() const { return count_; }

 private:
  Eigen::Matrix3d h_ = Eigen::Matrix3d::Zero();
  Vec3 first_from_ = Vec3::Zero(), first_to_ = Vec3::Zero();
  int count_ = 0;
};

/// The world turn of `joint` that best fits `fit`: about the hinge's world axis when the joint
/// has a hinge limit (its only freedom), the free best fit otherwise. `above` is the parent's
/// world rotation.
Quat best_turn(const BestFitRotation& fit, const Skeleton& skeleton,
               std::span<const JointLimit> limits, int joint, const Quat& above);

/// Whether `joint` has a hinge limit.
inline bool is_hinge(std::span<const JointLimit> limits, int joint) {
  return !limits.empty() &&
         std::holds_alternative<HingeLimit>(limits[static_cast<std::size_t>(joint)]);
}

/// The world rotation of `joint`'s parent (identity for a root).
inline Quat parent_rotation(const Skeleton& skeleton, const SkeletonPose& pose, int joint) {
  const int p = skeleton.parents()[static_cast<std::size_t>(joint)];
  return p < 0 ? Quat::Identity() : pose.global_rotations[static_cast<std::size_t>(p)];
}

/// The bend of kick(), radians: the angle the chain solvers kick a stalled chain by
/// (ik_common.h).
constexpr double kKickAngle = 0.2;

/// Turns every joint with effectors below it (scratch filled by index_effectors) by kKickAngle
/// about an axis perpendicular to its first such child's bone (in the joint's own frame),
/// inside its limit, and runs FK: a straight chain becomes an arc, which gives the solvers a
/// direction to bend in (on the line to its target, none of them finds one).
void kick(const Skeleton& skeleton, std::span<const JointLimit> limits,
          const TreeIkScratch& scratch, SkeletonPose& pose);

/// One iteration of a solver; leaves the pose consistent (FK run).
class TreeIteration {
 public:
  virtual void iterate(SkeletonPose& pose) = 0;

 protected:
  ~TreeIteration() = default;
};

/// The loop both solvers run: project the starting pose inside the limits, then iterate until
/// the errors are within tolerance, the cap is hit, or progress stalls (bending the joints
/// above the effectors a little to leave a singular pose, e.g. a straight chain on the line to
/// its target, where neither solver finds a direction). Ends with the best pose seen.
TreeIkResult run_tree_ik(const Skeleton& skeleton, const TreeIkProblem& problem,
                         const TreeLoopSettings& settings, TreeIkScratch& scratch,
                         SkeletonPose& pose, TreeIteration& iteration);

}  // namespace animkit::detail
