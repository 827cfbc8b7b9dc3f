#pragma once
// Jacobian damped least squares on skeleton trees, with several effectors, each with
// a position target, an optional orientation target and a weight, and joint limits enforced
// inside every iteration. Two step rules share the iteration:
//   DLS  (Wampler 1986; Buss 2004 "Introduction to inverse kinematics", eq. 11):
//        dtheta = J^T (J J^T + lambda^2 I)^-1 e
//   SDLS (Buss & Kim 2005, "Selectively damped least squares for inverse kinematics", sec. 4):
//        each singular direction's step is clamped by its own gamma_i <= gamma_max, so poorly
//        conditioned directions take small steps without damping the well conditioned ones.
// The signature is the tree solvers' shared one (tree_ik.h).
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <array>
#include <optional>
#include <vector>

#include "animkit/core/result.h"
#include "animkit/core/symmetric_eigen.h"
#include "animkit/core/types.h"
#include "animkit/kinematics/skeleton.h"
#include "animkit/kinematics/tree_ik.h"

namespace animkit {

/// Which step rule solve_dls_tree() takes.
enum class DlsMethod {
  damped,     ///< DLS with the fixed damping `lambda`
  selective,  ///< SDLS, per-singular-value damping clamped by `max_step_angle` (gamma_max)
};

/// Settings of solve_dls_tree(); the defaults suit skeletons in metres (a human ~1.7 m tall).
struct DlsSettings {
  /// The step rule: DLS (the default) or SDLS.
  DlsMethod method = DlsMethod::damped;
  int max_iterations = 100;  ///< DLS steps at most, >= 1
  double tolerance = 1e-4;   ///< largest effector position error to stop at (scene units), > 0
  /// Largest effector orientation error to stop at (radians), > 0; only effectors with an
  /// orientation target count.
  double angular_tolerance = 1e-4;
  /// DLS damping lambda in scene units, >= 0. It bounds the step where J is near singular
  /// (|dtheta| <= |e| / (2 lambda) per singular direction) and slows convergence only along
  /// directions whose singular value (about a lever arm in scene units) is below lambda, each
  /// iteration shrinking the error along one by lambda^2 / (sigma^2 + lambda^2). 0.02 m, a few
  /// percent of a limb's length: larger values stall short of a 1e-4 m tolerance on limbs held
  /// by their limits (tests/kinematics/dls_tree_test.cpp). Unused by SDLS.
  double lambda = 0.02;
  /// Largest joint rotation per iteration, radians, in (0, pi]: the whole step is scaled down so
  /// that no joint's rotation-vector component exceeds it (Buss & Kim's ClampMaxAbs). For SDLS
  /// it is gamma_max (the paper uses pi / 4).
  double max_step_angle = 0.785398163397448;  // pi / 4
  /// Scene units per radian that weigh an orientation error against a position error in the
  /// least squares (rows of an orientation target are scaled by weight * this), > 0.
  double orientation_weight = 1.0;

  /// The first problem ("DLS max_iterations must be >= 1, got 0"), or nothing.
  std::optional<Error> validate() const;
};

/// Scratch memory of solve_dls_tree(), owned by the caller and reused across calls. The solver
/// sizes it for the skeleton and effectors on first use; later calls with the same skeleton
/// size, effector count and orientation-target count allocate nothing (tests/allocation counts
/// it). Its contents between calls carry no state: a reused workspace gives the same bits as a
/// fresh one.
struct DlsWorkspace {
  Eigen::MatrixXd jacobian;  ///< rows: weighted effector errors; columns: 3 per joint (world)
  Eigen::VectorXd error;     ///< weighted effector errors (positions, then orientations)
  Eigen::MatrixXd jjt;       ///< J J^T (+ lambda^2 I for DLS)
  /// Computed once at construction (on a 1 x 1 identity) so that a fresh workspace can be copied
  /// or moved: a decomposition that never computed holds an uninitialized status.
  Eigen::LLT<Eigen::MatrixXd> llt{Eigen::MatrixXd::Identity(1, 1)};
  SymmetricEigen eigen;          ///< SDLS: J J^T = U S^2 U^T
  Eigen::MatrixXd jtu;           ///< SDLS: J^T U (columns sigma_i v_i)
  Eigen::VectorXd solve;         ///< (J J^T + lambda^2 I)^-1 e
  Eigen::VectorXd step;          ///< dtheta, 3 per joint (world)
  Eigen::VectorXd step_i;        ///< SDLS: one singular direction's
  Eigen::VectorXd column_norms;  ///< SDLS: rho_j, 3 per joint
  /// Per joint: up to two unit axes (parent frame) about which the last iteration's limit turned
  /// the joint back inward (a ball's swing and twist separately), zero when not active.
  std::vector<std::array<Vec3, 2>> pushed_back;
  /// Per joint, this iteration: bit k set when pushed_back[j][k] is taken out of its columns.
  std::vector<unsigned char> blocked;
  /// Effector bookkeeping for the kick out of a stalled, singular pose (tree_ik.h).
  TreeIkScratch scratch;
  /// The row count llt and eigen were last computed with (-1: never), so that resize() runs
  /// them once on a new size and they hold their memory before the first step needs them.
  int decomposed_rows = -1;

  /// Sizes everything, the decompositions included, for `skeleton` and the shape of `problem`
  /// (effector and orientation-target counts); allocates only when those change. Each solve
  /// does it first; a caller that may or may not solve (FABRIK's DLS finish) calls it so that
  /// a later solve allocates nothing.
  void resize(const Skeleton& skeleton, const TreeIkProblem& problem);
};

/// DLS or SDLS on a tree, same contract as every tree solver (tree_ik.h): the pose is the
/// starting guess and is overwritten with the solution (FK run); roots keep their translation
/// and, like every joint, may turn (a root that must not turn gets a limit with no range).
/// Each iteration builds the Jacobian of the weighted effector errors (position rows
/// omega x (p_e - p_j), orientation rows the identity, for every joint j above effector e,
/// roots included; a hinge's columns only along its axis, a ball without a cone's along its bone,
/// a limit with no range's none), takes the step, turns each joint's world
/// rotation by its rotation vector and constrains it by its limit. A joint resting on its limit
/// whose step points outward loses that direction (the gradient of the active constraint; a
/// ball's swing and twist apart) and the step is solved again (a clamping loop, Baerlocher &
/// Boulic 2004), so it does not keep pushing against the limit while others could move.
/// Limits are enforced after every iteration, so the result is always inside them. When the
/// error stops changing short of the tolerance (a straight limb on the line to its target has no
/// gradient toward it), the joints above the effectors are bent a little, as FABRIK and CCD do,
/// up to ten times.
/// Errors: validate_tree_ik's or settings.validate()'s message; the pose is then untouched.
Result<TreeIkResult> solve_dls_tree(const Skeleton& skeleton, const TreeIkProblem& problem,
                                    const DlsSettings& settings, DlsWorkspace& workspace,
                                    SkeletonPose& pose);

}  // namespace animkit
