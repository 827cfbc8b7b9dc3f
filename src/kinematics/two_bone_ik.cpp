#include "animkit/kinematics/two_bone_ik.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "animkit/core/quaternion_math.h"
#include "animkit/core/validation.h"

namespace animkit {

namespace {
// A bend whose sine is below this counts as a straight limb, whose bend plane is undefined.
constexpr double kMinBendSine = 1e-9;

std::optional<Error> check_point(const char* name, const Vec3& p) {
  if (is_finite(p)) return std::nullopt;
  return Error{std::string("two-bone ") + name + " has a non-finite coordinate " + to_string(p)};
}

// The part of v perpendicular to the unit u, normalized; nothing when shorter than `min`.
std::optional<Vec3> perpendicular_part(const Vec3& v, const Vec3& u, double min) {
  const Vec3 p = v - v.dot(u) * u;
  const double n = p.norm();
  if (!(n > min)) return std::nullopt;
  return Vec3(p / n);
}

// The rotation taking the orthonormal frame (a0, n0, a0 x n0) to (a1, n1, a1 x n1); n0 and n1
// are first made exactly perpendicular to a0 and a1 (Gram-Schmidt).
Quat frame_to_frame(const Vec3& a0, const Vec3& n0, const Vec3& a1, const Vec3& n1) {
  const Vec3 m0 = (n0 - n0.dot(a0) * a0).normalized();
  const Vec3 m1 = (n1 - n1.dot(a1) * a1).normalized();
  Eigen::Matrix3d from, to;
  from << a0, m0, a0.cross(m0);
  to << a1, m1, a1.cross(m1);
  return Quat(Eigen::Matrix3d(to * from.transpose())).normalized();
}

}  // namespace

std::optional<Error> TwoBoneInput::validate() const {
  for (const auto& [name, p] : {std::pair<const char*, const Vec3&>{"root", root},
                                {"middle", middle},
                                {"end", end},
                                {"target", target},
                                {"pole", pole}}) {
    if (auto e = check_point(name, p)) return e;
  }
  if ((middle - root).norm() < kMinBoneLength) {
    return Error{"two-bone upper bone (root to middle) has zero length"};
  }
  if ((end - middle).norm() < kMinBoneLength) {
    return Error{"two-bone lower bone (middle to end) has zero length"};
  }
  return std::nullopt;
}

std::optional<Error> TwoBoneSettings::validate() const {
  if (!(degenerate_length > 0.0) || !std::isfinite(degenerate_length)) {
    return Error{"two-bone degenerate_length must be positive and finite, got " +
                 format_number(degenerate_length)};
  }
  return std::nullopt;
}

Result<TwoBoneResult> solve_two_bone(const TwoBoneInput& in, const TwoBoneSettings& settings) {
  if (auto e = in.validate()) return fail(e->message);
  if (auto e = settings.validate()) return fail(e->message);
  const double eps = settings.degenerate_length;
  const Vec3 upper0 = in.middle - in.root, lower0 = in.end - in.middle;
  const double l1 = upper0.norm(), l2 = lower0.norm();

  // Direction u from the root to the target; a target at the root keeps the limb's direction.
  const Vec3 to_target = in.target - in.root;
  const double d = to_target.norm();
  const Vec3 reach0 = in.end - in.root;
  const Vec3 u = d > eps               ? Vec3(to_target / d)
                 : reach0.norm() > eps ? Vec3(reach0.normalized())
                                       : Vec3(upper0 / l1);

  // Bend direction b (unit, perpendicular to u): toward the pole; else toward where the middle
  // joint is now (the current bend plane); else any perpendicular.
  Vec3 b;
  if (auto p = perpendicular_part(in.pole - in.root, u, eps)) {
    b = *p;
  } else if (auto m = perpendicular_part(upper0, u, eps)) {
    b = *m;
  } else {
    b = perpendicular_axis(u);
  }

  // Law of cosines for the angle alpha at the root between u and the upper bone, with the
  // distance clamped to what the bones reach: l2^2 = l1^2 + dc^2 - 2 l1 dc cos(alpha).
  const double lo = std::abs(l1 - l2), hi = l1 + l2;
  const double dc = std::clamp(d, lo, hi);
  // At the ends of the reach the limb is straight; set that exactly, since the formula's
  // rounding (cos 1 - 1e-16) would leave a bend of sqrt(2e-16) and the middle joint off the line.
  double cos_a = 0.0;  // dc == 0: equal bones folded onto the root; any alpha works
  if (dc == hi) {
    cos_a = 1.0;
  } else if (dc == lo && lo > 0.0) {
    cos_a = l1 > l2 ? 1.0 : -1.0;
  } else if (dc > 0.0) {
    cos_a = std::clamp((l1 * l1 + dc * dc - l2 * l2) / (2.0 * l1 * dc), -1.0, 1.0);
  }
  const double sin_a = std::sqrt(std::max(0.0, (1.0 - cos_a) * (1.0 + cos_a)));
  const Vec3 upper1 = l1 * (cos_a * u + sin_a * b);
  const Vec3 lower1 = dc * u - upper1;  // from the new middle joint to the reached point

  // The new bend plane's normal is b x u (the sign of upper1 x lower1 when bent). The old one
  // is upper0 x lower0; a straight limb has none, so take the one the upper bone's shortest
  // arc carries onto the new normal, which makes the upper rotation that shortest arc.
  const Vec3 n1 = b.cross(u);
  const Vec3 bend0 = upper0.cross(lower0);
  const Vec3 n0 = bend0.norm() > kMinBendSine * l1 * l2 ? Vec3(bend0.normalized())
                                                        : Vec3(shortest_arc(upper1, upper0) * n1);

  TwoBoneResult r;
  r.upper_rotation = frame_to_frame(upper0 / l1, n0, upper1.normalized(), n1);
  r.lower_rotation = frame_to_frame(lower0 / l2, n0, lower1.normalized(), n1);
  r.middle = in.root + r.upper_rotation * upper0;
  r.end = r.middle + r.lower_rotation * lower0;
  r.reached = d >= lo && d <= hi;
  r.error = (r.end - in.target).norm();
  return r;
}

}  // namespace animkit
