// GCC 12's own AVX-512 intrinsics trip -Wuninitialized when Eigen's dense decompositions are
// inlined with -march=native at -O1 (the sanitizer build): a false positive in the compiler's
// headers (see psd_projection.cpp), silenced for this file only.
#pragma GCC diagnostic ignored "-Wuninitialized"

#include "animkit/kinematics/dls_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <variant>

#include "animkit/core/validation.h"
#include "limit_push.h"
#include "tree_ik_common.h"

namespace animkit {

namespace {

// skew(d) w = d x w.
Eigen::Matrix3d skew(const Vec3& d) {
  Eigen::Matrix3d m;
  m << 0.0, -d.z(), d.y(), d.z(), 0.0, -d.x(), -d.y(), d.x(), 0.0;
  return m;
}

const JointLimit* limit_of(const TreeIkProblem& problem, int joint) {
  return problem.limits.empty() ? nullptr : &problem.limits[static_cast<std::size_t>(joint)];
}

int orientation_count(const TreeIkProblem& problem) {
  int count = 0;
  for (const Effector& e : problem.effectors) count += e.orientation ? 1 : 0;
  return count;
}

// Sizes the workspace; Eigen's resize keeps the memory when the size is unchanged.
void size_workspace(DlsWorkspace& ws, int joints, int rows) {
  const int cols = 3 * joints;
  ws.jacobian.resize(rows, cols);
  ws.error.resize(rows);
  ws.jjt.resize(rows, rows);
  ws.jtu.resize(cols, rows);
  ws.solve.resize(rows);
  ws.step.resize(cols);
  ws.step_i.resize(cols);
  ws.column_norms.resize(cols);
  ws.pushed_back.assign(static_cast<std::size_t>(joints), {Vec3::Zero(), Vec3::Zero()});
  ws.blocked.assign(static_cast<std::size_t>(joints), 0);
  ws.scratch.resize(joints);
  if (ws.decomposed_rows != rows) {
    // Computed once on a matrix of the new size, so that the decompositions own their memory
    // (they size it in compute(), never before).
    ws.jjt.setIdentity();
    ws.llt.compute(ws.jjt);
    ws.eigen.compute(ws.jjt);
    ws.decomposed_rows = rows;
  }
}

// Rows of the weighted error e and its Jacobian J (d e / d omega_j, omega_j joint j's world
// angular step): an effector's position rows are w (target - p_e) and, for each joint j strictly
// above it, root included (roots turn, tree_ik.h), w (omega_j x (p_e - p_j)) = -w skew(p_e - p_j)
// omega_j; its orientation rows are w_o rotvec(target * current^-1) and w_o I for j the effector
// or above it.
void build_rows(const Skeleton& skeleton, const TreeIkProblem& problem, const DlsSettings& s,
                const SkeletonPose& pose, DlsWorkspace& ws) {
  ws.jacobian.setZero();
  const auto& parents = skeleton.parents();
  int row = 0;
  for (const Effector& e : problem.effectors) {
    const Vec3& p = pose.global_positions[static_cast<std::size_t>(e.joint)];
    ws.error.segment<3>(row) = e.weight * (e.position - p);
    for (int j = parents[static_cast<std::size_t>(e.joint)]; j >= 0;
         j = parents[static_cast<std::size_t>(j)]) {
      const Vec3 d = p - pose.global_positions[static_cast<std::size_t>(j)];
      ws.jacobian.block<3, 3>(row, 3 * j) = -e.weight * skew(d);
    }
    row += 3;
  }
  for (const Effector& e : problem.effectors) {
    if (!e.orientation) continue;
    const double w = e.weight * s.orientation_weight;
    const Quat& q = pose.global_rotations[static_cast<std::size_t>(e.joint)];
    ws.error.segment<3>(row) = w * rotation_vector(*e.orientation * q.conjugate());
    for (int j = e.joint; j >= 0; j = parents[static_cast<std::size_t>(j)]) {
      ws.jacobian.block<3, 3>(row, 3 * j) = w * Eigen::Matrix3d::Identity();
    }
    row += 3;
  }
}

// A joint moves only along the freedoms its limit has, and its columns keep those alone: a
// hinge turns about its axis (world axis = global rotation * rest-frame axis, since q_rel is a
// rotation about it), a ball without a cone about its bone only (its twist axis, likewise), and
// a limit with no range at all (a held root, tree_ik.h) not at all. Otherwise the step would
// count on turns the limit takes back after it, one direction at a time.
void restrict_to_limit(const TreeIkProblem& problem, const SkeletonPose& pose, int j,
                       DlsWorkspace& ws) {
  const JointLimit* limit = limit_of(problem, j);
  if (limit == nullptr) return;
  Vec3 axis;
  bool turns = true;
  if (const auto* hinge = std::get_if<HingeLimit>(limit)) {
    axis = hinge->axis;
    turns = hinge->min_angle < hinge->max_angle;
  } else if (const auto* ball = std::get_if<BallLimit>(limit);
             ball != nullptr && ball->swing_angle == 0.0 &&
             ball->swing_angle_2.value_or(0.0) == 0.0) {
    axis = ball->twist_axis;
    turns = ball->min_twist < ball->max_twist;
  } else {
    return;
  }
  auto cols = ws.jacobian.middleCols<3>(3 * j);
  if (!turns) {
    cols.setZero();
    return;
  }
  const Vec3 a = (pose.global_rotations[static_cast<std::size_t>(j)] * axis).normalized();
  // Row by row with fixed-size rows: a product of the whole block would allocate a temporary.
  for (Eigen::Index r = 0; r < cols.rows(); ++r) cols.row(r) = cols.row(r).dot(a) * a.transpose();
}

// Takes push axis k of joint j (world `inward`) out of its columns, orthogonal to the axis
// blocked before it, so that two blocked axes remove exactly their span.
void block_axis(const SkeletonPose& pose, const Skeleton& skeleton, int j, unsigned k,
                DlsWorkspace& ws) {
  const auto ju = static_cast<std::size_t>(j);
  const Quat g = detail::parent_rotation(skeleton, pose, j);
  Vec3 r = g * ws.pushed_back[ju][k];
  if (ws.blocked[ju] & (1u << (1 - k))) {
    const Vec3 other = (g * ws.pushed_back[ju][1 - k]).normalized();
    r -= r.dot(other) * other;
  }
  ws.blocked[ju] = static_cast<unsigned char>(ws.blocked[ju] | (1u << k));
  const double n = r.norm();
  if (n < 1e-9) return;  // already out of the columns
  r /= n;
  auto cols = ws.jacobian.middleCols<3>(3 * j);
  for (Eigen::Index row = 0; row < cols.rows(); ++row) {
    cols.row(row) -= cols.row(row).dot(r) * r.transpose();
  }
}

// Buss & Kim 2005's ClampMaxAbs: scales w so that its largest |component| is at most d.
void clamp_max_abs(Eigen::VectorXd& w, double d) {
  const double m = w.cwiseAbs().maxCoeff();
  if (m > d) w *= d / m;
}

// DLS: dtheta = J^T (J J^T + lambda^2 I)^-1 e, by Cholesky of the small m x m matrix.
void dls_step(const DlsSettings& s, DlsWorkspace& ws) {
  ws.jjt.noalias() = ws.jacobian * ws.jacobian.transpose();
  ws.jjt.diagonal().array() += s.lambda * s.lambda;
  // lambda = 0 with a singular J: a tiny ridge keeps the factorization defined.
  ws.jjt.diagonal().array() += 1e-12;
  ws.llt.compute(ws.jjt);
  ws.solve = ws.llt.solve(ws.error);
  ws.step.noalias() = ws.jacobian.transpose() * ws.solve;
  clamp_max_abs(ws.step, s.max_step_angle);
}

// SDLS, Buss & Kim 2005, sec. 4, from J J^T = U S^2 U^T (v_i = J^T u_i / sigma_i). For each
// sigma_i > 0: alpha_i = u_i . e; N_i = sum over effectors of |u_i's 3-row block|; M_i =
// sigma_i^-1 sum_j |v_ij| rho_j with rho_j = sum over effectors of |J's 3-row block of column
// j|; gamma_i = min(1, N_i / M_i) gamma_max; phi_i = ClampMaxAbs(alpha_i / sigma_i v_i, gamma_i);
// dtheta = ClampMaxAbs(sum phi_i, gamma_max).
void sdls_step(const DlsSettings& s, DlsWorkspace& ws) {
  const auto rows = ws.jacobian.rows();
  const auto blocks = rows / 3;
  ws.jjt.noalias() = ws.jacobian * ws.jacobian.transpose();
  ws.eigen.compute(ws.jjt);
  ws.jtu.noalias() = ws.jacobian.transpose() * ws.eigen.eigenvectors();
  for (Eigen::Index c = 0; c < ws.jacobian.cols(); ++c) {
    double rho = 0.0;
    for (Eigen::Index b = 0; b < blocks; ++b) rho += ws.jacobian.col(c).segment<3>(3 * b).norm();
    ws.column_norms[c] = rho;
  }
  const double largest = std::max(ws.eigen.eigenvalues().maxCoeff(), 0.0);
  ws.step.setZero();
  for (Eigen::Index i = 0; i < rows; ++i) {
    const double sigma2 = ws.eigen.eigenvalues()[i];
    if (!(sigma2 > 1e-20 * largest) || sigma2 <= 0.0) continue;  // rank deficient direction
    const auto u = ws.eigen.eigenvectors().col(i);
    const double alpha = u.dot(ws.error);
    double n = 0.0;
    for (Eigen::Index b = 0; b < blocks; ++b) n += u.segment<3>(3 * b).norm();
    // v_i = jtu_i / sigma; M_i = sum_j |v_ij| rho_j / sigma.
    const double m = ws.jtu.col(i).cwiseAbs().dot(ws.column_norms) / sigma2;
    const double gamma = (m > n ? n / m : 1.0) * s.max_step_angle;
    ws.step_i = (alpha / sigma2) * ws.jtu.col(i);
    clamp_max_abs(ws.step_i, gamma);
    ws.step += ws.step_i;
  }
  clamp_max_abs(ws.step, s.max_step_angle);
}

void take_step(const DlsSettings& s, DlsWorkspace& ws) {
  if (s.method == DlsMethod::selective) {
    sdls_step(s, ws);
  } else {
    dls_step(s, ws);
  }
}

// Turns each joint, roots included, by its world rotation vector (G' = exp(dtheta) G, so the
// local rotation becomes exp(G_p^-1 dtheta) L, with the parents' rotations of the
// linearization) and constrains it by its limit, remembering the limit's push-back axes.
void apply_step(const Skeleton& skeleton, const TreeIkProblem& problem, SkeletonPose& pose,
                DlsWorkspace& ws) {
  for (int j = 0; j < skeleton.joint_count(); ++j) {
    const auto ju = static_cast<std::size_t>(j);
    const Vec3 dtheta = ws.step.segment<3>(3 * j);
    Quat& local = pose.local_rotations[ju];
    if (dtheta.squaredNorm() > 0.0) {
      const Vec3 r = detail::parent_rotation(skeleton, pose, j).conjugate() * dtheta;
      local = (from_rotation_vector(r) * local).normalized();
    }
    std::array<Vec3, 2>& pushed = ws.pushed_back[ju];
    const JointLimit* limit = limit_of(problem, j);
    if (limit == nullptr || std::holds_alternative<FreeJoint>(*limit)) {
      pushed = {Vec3::Zero(), Vec3::Zero()};
      continue;
    }
    const Quat& rest = skeleton.rest_rotations()[ju];
    // A push stays active while the joint rests on the limit it was held against (blocked this
    // iteration), so it is not released to push out again every other iteration; a joint that
    // moved off the limit is free again.
    for (unsigned k = 0; k < 2; ++k) {
      if (!(ws.blocked[ju] & (1u << k)) || !at_limit(*limit, rest, local, pushed[k]))
        pushed[k].setZero();
    }
    const Quat wanted = local;
    local = rest * constrain(*limit, rest.conjugate() * local);
    if (local.coeffs() == wanted.coeffs()) continue;
    const std::array<Vec3, 2> axes = limit_push_axes(*limit, rest, wanted, local);
    for (unsigned k = 0; k < 2; ++k) {
      if (!axes[k].isZero()) pushed[k] = axes[k];
    }
  }
}

}  // namespace

void DlsWorkspace::resize(const Skeleton& skeleton, const TreeIkProblem& problem) {
  size_workspace(*this, skeleton.joint_count(),
                 3 * (static_cast<int>(problem.effectors.size()) + orientation_count(problem)));
}

std::optional<Error> DlsSettings::validate() const {
  if (max_iterations < 1)
    return Error{"DLS max_iterations must be >= 1, got " + std::to_string(max_iterations)};
  if (!(std::isfinite(tolerance) && tolerance > 0.0))
    return Error{"DLS tolerance must be finite and > 0, got " + format_number(tolerance)};
  if (!(std::isfinite(angular_tolerance) && angular_tolerance > 0.0)) {
    return Error{"DLS angular_tolerance must be finite and > 0, got " +
                 format_number(angular_tolerance)};
  }
  if (!(std::isfinite(lambda) && lambda >= 0.0))
    return Error{"DLS lambda must be finite and >= 0, got " + format_number(lambda)};
  if (!(max_step_angle > 0.0 && max_step_angle <= std::numbers::pi)) {
    return Error{"DLS max_step_angle must be in (0, pi], got " + format_number(max_step_angle)};
  }
  if (!(std::isfinite(orientation_weight) && orientation_weight > 0.0)) {
    return Error{"DLS orientation_weight must be finite and > 0, got " +
                 format_number(orientation_weight)};
  }
  return std::nullopt;
}

Result<TreeIkResult> solve_dls_tree(const Skeleton& skeleton, const TreeIkProblem& problem,
                                    const DlsSettings& settings, DlsWorkspace& workspace,
                                    SkeletonPose& pose) {
  if (auto error = validate_tree_ik(skeleton, problem, pose)) return std::unexpected(*error);
  if (auto error = settings.validate()) return std::unexpected(*error);
  const int joints = skeleton.joint_count();
  const int rows = 3 * (static_cast<int>(problem.effectors.size()) + orientation_count(problem));
  DlsWorkspace& ws = workspace;
  size_workspace(ws, joints, rows);

  // The starting guess may lie outside the limits: constrain it first (a zero step).
  ws.step.setZero();
  std::fill(ws.blocked.begin(), ws.blocked.end(), 0);
  skeleton_forward_kinematics(skeleton, pose);
  apply_step(skeleton, problem, pose, ws);
  skeleton_forward_kinematics(skeleton, pose);

  TreeIkResult result;
  result.reachable = tree_ik_reachable(skeleton, pose, problem.effectors);
  auto done = [&](const TreeIkErrors& errors) {
    return errors.position <= settings.tolerance &&
           errors.orientation <= settings.angular_tolerance;
  };
  // A straight limb on the line to its target (the lab's arm at rest) has no gradient toward
  // it: an iteration that changes the error by less than this fraction makes no progress, and
  // after kStallIterations of them the joints above the effectors are bent (detail::kick, as
  // FABRIK and CCD do), at most kMaxKicks times.
  constexpr double kStallRatio = 1e-6;
  constexpr int kStallIterations = 3;
  constexpr int kMaxKicks = 10;
  detail::index_effectors(skeleton, problem.effectors, ws.scratch);
  int stalled = 0, kicks = 0;
  TreeIkErrors errors = tree_ik_errors(pose, problem.effectors);
  // A kick leaves the pose it bends; the best pose seen before any kick is kept, and returned
  // if the solve ends worse (a kick near the iteration cap, or an out-of-reach target whose
  // straight limb stalls and is kicked again and again).
  auto total = [](const TreeIkErrors& e) { return e.position + e.orientation; };
  double best_total = std::numeric_limits<double>::infinity();
  auto& best_rotations = ws.scratch.best_local_rotations;
  while (!done(errors) && result.iterations < settings.max_iterations) {
    const double before = errors.position + errors.orientation;
    build_rows(skeleton, problem, settings, pose, ws);
    std::fill(ws.blocked.begin(), ws.blocked.end(), 0);
    for (int j = 0; j < joints; ++j) restrict_to_limit(problem, pose, j, ws);
    take_step(settings, ws);
    // Clamping loop (Baerlocher & Boulic 2004): a joint its limit pushed back last iteration
    // whose step points outward again loses that direction, and the step is taken anew.
    for (int pass = 0; pass < 3; ++pass) {
      bool blocked_any = false;
      for (int j = 0; j < joints; ++j) {
        const auto ju = static_cast<std::size_t>(j);
        const Quat g = detail::parent_rotation(skeleton, pose, j);
        for (unsigned k = 0; k < 2; ++k) {
          const Vec3& inward = ws.pushed_back[ju][k];
          if ((ws.blocked[ju] & (1u << k)) || inward.isZero()) continue;
          if (ws.step.segment<3>(3 * j).dot(g * inward) >= 0.0) continue;
          block_axis(pose, skeleton, j, k, ws);
          blocked_any = true;
        }
      }
      if (!blocked_any) break;
      take_step(settings, ws);
    }
    apply_step(skeleton, problem, pose, ws);
    skeleton_forward_kinematics(skeleton, pose);
    ++result.iterations;
    errors = tree_ik_errors(pose, problem.effectors);
    const double after = errors.position + errors.orientation;
    stalled = std::abs(after - before) <= kStallRatio * before ? stalled + 1 : 0;
    if (stalled >= kStallIterations && kicks < kMaxKicks && !done(errors) &&
        result.iterations < settings.max_iterations) {
      if (total(errors) < best_total) {
        best_total = total(errors);
        std::copy(pose.local_rotations.begin(), pose.local_rotations.end(), best_rotations.begin());
      }
      ++kicks;
      stalled = 0;
      detail::kick(skeleton, problem.limits, ws.scratch, pose);
      errors = tree_ik_errors(pose, problem.effectors);
    }
  }
  if (best_total < total(errors)) {
    std::copy(best_rotations.begin(), best_rotations.end(), pose.local_rotations.begin());
    skeleton_forward_kinematics(skeleton, pose);
    errors = tree_ik_errors(pose, problem.effectors);
  }
  result.error = errors.position;
  result.orientation_error = errors.orientation;
  result.converged = done(errors);
  return result;
}

}  // namespace animkit
