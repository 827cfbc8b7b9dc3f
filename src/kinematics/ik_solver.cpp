#include "animkit/kinematics/ik_solver.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "animkit/core/quaternion_math.h"
#include "animkit/core/validation.h"
#include "animkit/kinematics/forward_kinematics.h"
#include "ik_common.h"

namespace animkit {

std::optional<Error> IkOptions::validate() const {
  if (max_iterations < 1) {
    return Error{"max iterations must be at least 1, got " + std::to_string(max_iterations)};
  }
  // isfinite first: an ordered comparison with NaN raises FE_INVALID, which the tests trap.
  if (!std::isfinite(tolerance) || tolerance <= 0.0) {
    return Error{"tolerance must be a positive finite number, got " + format_number(tolerance)};
  }
  return std::nullopt;
}

std::string_view to_string(IkSolverKind kind) {
  switch (kind) {
    case IkSolverKind::ccd:
      return "ccd";
    case IkSolverKind::fabrik:
      return "fabrik";
  }
  return "unknown";
}

std::span<const IkSolverKind> all_ik_solvers() {
  static constexpr std::array kinds{IkSolverKind::ccd, IkSolverKind::fabrik};
  return kinds;
}

std::optional<IkSolverKind> parse_ik_solver(std::string_view name) {
  for (IkSolverKind kind : all_ik_solvers()) {
    if (name == to_string(kind)) return kind;
  }
  return std::nullopt;
}

std::string_view to_string(FabrikRotations mode) {
  return mode == FabrikRotations::from_rest ? "rest" : "previous";
}

std::optional<FabrikRotations> parse_fabrik_rotations(std::string_view name) {
  if (name == "rest") return FabrikRotations::from_rest;
  if (name == "previous") return FabrikRotations::from_previous;
  return std::nullopt;
}

Result<IkResult> solve_ik(IkSolverKind kind, const Chain& chain, Pose& pose, const Vec3& target,
                          const IkOptions& options) {
  auto result = kind == IkSolverKind::ccd ? solve_ccd(chain, pose, target, options)
                                          : solve_fabrik(chain, pose, target, options);
  // Inputs are checked, so this cannot happen short of a solver bug; if it does, a NaN error
  // must never read as a converged solve.
  if (result && !std::isfinite(result->error)) {
    return fail(std::string(to_string(kind)) + " produced a non-finite error for target " +
                to_string(target));
  }
  return result;
}

namespace detail {

namespace {

std::optional<Error> validate_ik_input(const Chain& chain, const Pose& pose, const Vec3& target,
                                       const IkOptions& options) {
  if (!is_finite(target)) {
    return Error{"target has a non-finite coordinate " + to_string(target)};
  }
  if (target.cwiseAbs().maxCoeff() > kMaxTargetCoordinate) {
    return Error{"target " + to_string(target) + " has a coordinate beyond +-" +
                 format_number(kMaxTargetCoordinate) + ", farther than a solve can place a chain"};
  }
  const std::size_t n = chain.local_offsets().size();
  const auto mismatch = [n](std::size_t size, const char* what) {
    return Error{"pose has " + std::to_string(size) + " " + what + " but the chain has " +
                 std::to_string(n) + " joints"};
  };
  if (pose.local_rotations.size() != n)
    return mismatch(pose.local_rotations.size(), "local rotations");
  if (pose.global_rotations.size() != n)
    return mismatch(pose.global_rotations.size(), "global rotations");
  if (pose.global_positions.size() != n)
    return mismatch(pose.global_positions.size(), "joint positions");
  // The pose is the warm start: a corrupted one would turn into NaN or stretched bones. This
  // runs on every solve, so the common case is one pass of sums (NaN and inf propagate into
  // them quietly), and only a failed check walks the joints again to name the culprit.
  double finite_sum = 0.0, unit_deviation = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    unit_deviation += std::abs(pose.local_rotations[i].squaredNorm() - 1.0);
    finite_sum += pose.global_positions[i].sum() + pose.global_rotations[i].coeffs().sum();
  }
  if (std::isfinite(finite_sum) && std::isfinite(unit_deviation) && unit_deviation <= 1e-6) {
    return options.validate();
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Quat& q = pose.local_rotations[i];
    if (!is_finite(q) || std::abs(q.squaredNorm() - 1.0) > 1e-6) {
      return Error{"pose joint " + std::to_string(i) + " rotation is not a finite unit quaternion"};
    }
    if (!is_finite(pose.global_positions[i]) || !is_finite(pose.global_rotations[i])) {
      return Error{"pose joint " + std::to_string(i) + " has a non-finite position or rotation"};
    }
  }
  return Error{"pose rotations are not unit quaternions"};  // deviations too small one by one
}

}  // namespace

std::optional<Result<IkResult>> settle_without_iterating(const Chain& chain, Pose& pose,
                                                         const Vec3& target,
                                                         const IkOptions& options) {
  if (auto error = validate_ik_input(chain, pose, target, options)) return fail(error->message);
  const double straight = std::max(chain.reach() - options.tolerance, 0.0);
  if ((target - chain.root_position()).squaredNorm() >= straight * straight) {
    return point_chain_at(chain, pose, target, options);
  }
  return std::nullopt;
}

bool within_reach(const Chain& chain, const Vec3& target) {
  const double distance2 = (target - chain.root_position()).squaredNorm();
  return distance2 <= chain.reach() * chain.reach() &&
         distance2 >= chain.min_reach() * chain.min_reach();
}

bool on_singular_line(const Chain& chain, const std::vector<Vec3>& positions, const Vec3& target) {
  const Vec3& root = chain.root_position();
  Vec3 line = target - root;
  if (line.squaredNorm() == 0.0) line = positions.back() - root;
  if (line.squaredNorm() == 0.0) return true;
  line.normalize();
  const double slack = 1e-9 * chain.reach();
  for (const Vec3& p : positions) {
    if ((p - root).cross(line).squaredNorm() > slack * slack) return false;
  }
  return true;
}

void prefer_straight_if_nearer(const Chain& chain, Pose& pose, const Vec3& target,
                               const IkOptions& options, IkResult& result) {
  if (result.converged) return;
  // The straight chain ends at full reach on the ray from the root through the target.
  const double straight_error = std::abs((target - chain.root_position()).norm() - chain.reach());
  if (straight_error >= result.error) return;
  const int iterations = result.iterations;
  result = point_chain_at(chain, pose, target, options);
  result.iterations = iterations;
}

Quat stall_kick(const Chain& chain, const Pose& pose, const Vec3& target) {
  constexpr double kStallKickAngle = 0.2;
  Vec3 line = target - chain.root_position();
  if (line.squaredNorm() == 0.0) line = pose.end_effector() - chain.root_position();
  return Quat(Eigen::AngleAxisd(kStallKickAngle, perpendicular_axis(line)));
}

IkResult point_chain_at(const Chain& chain, Pose& pose, const Vec3& target,
                        const IkOptions& options) {
  const int n = chain.joint_count();
  Vec3 direction = target - chain.root_position();
  if (direction.squaredNorm() == 0.0) direction = pose.end_effector() - chain.root_position();
  // Every bone along `direction`: global_rotation[i] maps bone i+1's rest offset onto it.
  Quat parent = Quat::Identity();
  for (int i = 0; i + 1 < n; ++i) {
    const Quat global = shortest_arc(chain.local_offsets()[i + 1], direction);
    pose.local_rotations[i] = (parent.conjugate() * global).normalized();
    parent = global;
  }
  forward_kinematics(chain, pose, 0);
  IkResult result;
  result.error = (pose.end_effector() - target).norm();
  result.converged = result.error <= options.tolerance;
  result.reachable = within_reach(chain, target);
  return result;
}

}  // namespace detail
}  // namespace animkit
