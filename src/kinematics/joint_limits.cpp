#include "animkit/kinematics/joint_limits.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "animkit/core/quaternion_math.h"
#include "animkit/core/validation.h"
#include "swing_ellipse.h"

namespace animkit {

namespace {
constexpr double kPi = std::numbers::pi;

std::optional<Error> check_axis(const char* what, const Vec3& axis) {
  if (!is_finite(axis)) return Error{std::string(what) + " has a non-finite coordinate"};
  if (std::abs(axis.norm() - 1.0) > kUnitTolerance) {
    return Error{std::string(what) + " is not unit length (norm " + format_number(axis.norm()) +
                 ")"};
  }
  return std::nullopt;
}

// `what` stays a C string until there is an error: solvers validate limits on every call and
// must not allocate then.
std::optional<Error> check_range(const char* what, double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) {
    return Error{std::string(what) + " has a non-finite angle"};
  }
  if (lo < -kPi || hi > kPi) {
    return Error{std::string(what) + " [" + format_number(lo) + ", " + format_number(hi) +
                 "] rad is not within [-pi, pi]"};
  }
  if (lo > hi) {
    return Error{std::string(what) + " minimum " + format_number(lo) + " rad is above its maximum " +
                 format_number(hi) + " rad"};
  }
  return std::nullopt;
}

// q and -q are one rotation; pick the sign with w > 0, breaking a tie at w == 0 by the first
// non-zero of (twist component, x, y, z) so that q and -q decompose to the same quaternions.
Quat canonical(const Quat& q, const Vec3& axis) {
  const double keys[] = {q.w(), q.vec().dot(axis), q.x(), q.y(), q.z()};
  for (double k : keys) {
    if (k > 0.0) return q;
    if (k < 0.0) return Quat(-q.w(), -q.x(), -q.y(), -q.z());
  }
  return q;
}

// Angle in [0, pi] of a unit quaternion with w >= 0 (atan2: accurate near 0 and near pi).
double angle_of(const Quat& q) {
  return 2.0 * std::atan2(q.vec().norm(), std::abs(q.w()));
}

// x wrapped into [-pi, pi].
double wrap(double x) {
  return x - 2.0 * kPi * std::round(x / (2.0 * kPi));
}

// Whether the rotation angle `angle` (any representative mod 2 pi) lies in [lo, hi], give or
// take `slack`.
bool in_range(double angle, double lo, double hi, double slack = kJointLimitTolerance) {
  for (double a : {angle, angle - 2.0 * kPi, angle + 2.0 * kPi}) {
    if (a >= lo - slack && a <= hi + slack) return true;
  }
  return false;
}

// Distances round the circle from `angle` to the range's two ends; outside the range the
// nearest angle inside is the nearer end (the range is an arc shorter than the full circle).
double distance_to_end(double angle, double end) {
  return std::abs(wrap(angle - end));
}

// The nearest angle in [lo, hi] to an `angle` outside it.
double clamp_outside_angle(double angle, double lo, double hi) {
  return distance_to_end(angle, lo) <= distance_to_end(angle, hi) ? lo : hi;
}

double angle_excess(double angle, double lo, double hi, double slack) {
  if (in_range(angle, lo, hi, slack)) return 0.0;
  return std::min(distance_to_end(angle, lo), distance_to_end(angle, hi));
}

Quat about_axis(double angle, const Vec3& unit_axis) {
  const Vec3 v = std::sin(0.5 * angle) * unit_axis;
  return Quat(std::cos(0.5 * angle), v.x(), v.y(), v.z());
}

// The parts of q a limit looks at, with the axis made exactly unit.
struct Parts {
  SwingTwist st;
  double swing = 0.0;  // radians, [0, pi]
  double twist = 0.0;  // radians, [-pi, pi]
  // How far the twist angle can be off by rounding alone. twist = 2 atan2(v.axis, w) with n =
  // |(w, v.axis)| = cos(swing / 2): components rounded by a few eps move it by ~eps / n, which
  // grows without bound as the swing nears a half turn (where the twist is undefined).
  double twist_slack = kJointLimitTolerance;
};

Parts parts_of(const Quat& q, const Vec3& unit_axis) {
  Parts p;
  p.st = swing_twist(q, unit_axis);
  p.swing = angle_of(p.st.swing);
  p.twist = twist_angle(p.st.twist, unit_axis);
  const double n = p.st.swing.w();
  const double noise = 16.0 * std::numeric_limits<double>::epsilon();
  if (n * kJointLimitTolerance < noise) {
    p.twist_slack = n > 1e-300 ? noise / n : std::numeric_limits<double>::infinity();
  }
  return p;
}

bool hinge_inside(const HingeLimit& h, const Parts& p) {
  return p.swing <= kJointLimitTolerance && in_range(p.twist, h.min_angle, h.max_angle);
}

// A ball's swing against its cone: how far beyond it, and the swing to use in a constrained
// rotation (the swing itself when strictly inside, no tolerance, else the nearest in the cone).
struct BallSwing {
  double excess = 0.0;  // radians; the rotation vector's distance to an elliptical cone
  Quat clamped;
};

BallSwing ball_swing(const BallLimit& b, const Vec3& axis, const Parts& p) {
  const Vec3& v = p.st.swing.vec();
  if (!b.swing_angle_2) {
    // The swing turns the bone from `axis` along a great circle; stopping it at the cone's
    // edge on that circle is the direction in the cone nearest the bone's (geodesic distance).
    // swing > cone >= 0 there, so the swing's axis is defined.
    if (p.swing <= b.swing_angle) return {0.0, p.st.swing};
    return {p.swing - b.swing_angle, about_axis(b.swing_angle, v.normalized())};
  }
  const double n = v.norm();
  if (n == 0.0) return {0.0, p.st.swing};  // no swing is inside every cone
  // The rotation vector r = angle * unit axis, in the cone's plane coordinates.
  const Vec3 e1 = (b.swing_axis - b.swing_axis.dot(axis) * axis).normalized();
  const Vec3 e2 = axis.cross(e1);
  const Vec3 r = (p.swing / n) * v;
  const Eigen::Vector2d r2(r.dot(e1), r.dot(e2));
  const Eigen::Vector2d near = nearest_in_ellipse(r2, b.swing_angle, *b.swing_angle_2);
  if (near == r2) return {0.0, p.st.swing};
  const Vec3 rv = near.x() * e1 + near.y() * e2;
  const double angle = rv.norm();
  return {(r2 - near).norm(), angle > 0.0 ? about_axis(angle, rv / angle) : Quat::Identity()};
}

Quat constrain_hinge(const HingeLimit& h, const Quat& q) {
  const Vec3 axis = h.axis.normalized();
  const Parts p = parts_of(q, axis);
  if (hinge_inside(h, p)) return q;
  // The nearest rotation about the axis is q's twist: for r = (cos t/2, sin t/2 axis),
  // |<q, r>| = n |cos((t - phi)/2)| with n = |(w, v.axis)| and phi the twist angle, which is
  // largest (the rotation between them smallest) for t nearest phi round the circle.
  // A new rotation keeps a part only if it is strictly inside (no tolerance), so that the
  // result's rounding cannot take it past the tolerance; otherwise the part goes to the end.
  if (in_range(p.twist, h.min_angle, h.max_angle, 0.0)) return p.st.twist;
  return about_axis(clamp_outside_angle(p.twist, h.min_angle, h.max_angle), axis);
}

Quat constrain_ball(const BallLimit& b, const Quat& q) {
  const Vec3 axis = b.twist_axis.normalized();
  const Parts p = parts_of(q, axis);
  const BallSwing swing = ball_swing(b, axis, p);
  const bool twist_ok = in_range(p.twist, b.min_twist, b.max_twist, p.twist_slack);
  if (swing.excess <= kJointLimitTolerance && twist_ok) return q;
  // As for the hinge, a part is kept only if strictly inside: its tolerance (or the twist's
  // slack) may not hold for the new rotation.
  const Quat twist = in_range(p.twist, b.min_twist, b.max_twist, 0.0)
                         ? p.st.twist
                         : about_axis(clamp_outside_angle(p.twist, b.min_twist, b.max_twist), axis);
  return (swing.clamped * twist).normalized();
}

}  // namespace

std::optional<Error> HingeLimit::validate() const {
  if (auto e = check_axis("hinge axis", axis)) return e;
  return check_range("hinge angle range", min_angle, max_angle);
}

std::optional<Error> BallLimit::validate() const {
  if (auto e = check_axis("ball twist axis", twist_axis)) return e;
  for (const double angle : {swing_angle, swing_angle_2.value_or(0.0)}) {
    if (!std::isfinite(angle) || angle < 0.0 || angle > kPi) {
      return Error{"ball swing cone half-angle " + format_number(angle) +
                   " rad is not within [0, pi]"};
    }
  }
  if (swing_angle_2) {
    if (auto e = check_axis("ball swing axis", swing_axis)) return e;
    if (std::abs(swing_axis.dot(twist_axis)) > kUnitTolerance) {
      return Error{"ball swing axis is not perpendicular to the twist axis (cosine " +
                   format_number(swing_axis.dot(twist_axis)) + ")"};
    }
  }
  return check_range("ball twist range", min_twist, max_twist);
}

std::optional<Error> validate(const JointLimit& limit) {
  if (const auto* h = std::get_if<HingeLimit>(&limit)) return h->validate();
  if (const auto* b = std::get_if<BallLimit>(&limit)) return b->validate();
  return std::nullopt;
}

SwingTwist swing_twist(const Quat& q, const Vec3& axis) {
  // Twist = q's projection onto the rotations about `axis`, (w, (v.axis) axis), normalized;
  // swing = q * conj(twist), whose vector part is perpendicular to the axis. With w >= 0 both
  // parts have w >= 0. hypot keeps n accurate where w and v.axis are tiny (swing near pi).
  const Quat c = canonical(q, axis);
  const double t = c.vec().dot(axis);
  const double n = std::hypot(c.w(), t);
  SwingTwist out{c, Quat::Identity()};
  if (n == 0.0) return out;  // a swing of exactly pi: every twist fits; take none
  const Vec3 tv = (t / n) * axis;
  out.twist = Quat(c.w() / n, tv.x(), tv.y(), tv.z()).normalized();
  Quat swing = c * out.twist.conjugate();
  // Remove the rounding left along the axis so the swing's axis is perpendicular to it.
  swing.vec() -= swing.vec().dot(axis) * axis;
  out.swing = swing.normalized();
  return out;
}

double twist_angle(const Quat& twist, const Vec3& axis) {
  return 2.0 * std::atan2(twist.vec().dot(axis), twist.w());
}

Quat constrain(const JointLimit& limit, const Quat& q) {
  if (const auto* h = std::get_if<HingeLimit>(&limit)) return constrain_hinge(*h, q);
  if (const auto* b = std::get_if<BallLimit>(&limit)) return constrain_ball(*b, q);
  return q;
}

double violation(const JointLimit& limit, const Quat& q) {
  if (const auto* h = std::get_if<HingeLimit>(&limit)) {
    if (hinge_inside(*h, parts_of(q, h->axis.normalized()))) return 0.0;
    return rotation_angle_between(q, constrain_hinge(*h, q));
  }
  if (const auto* b = std::get_if<BallLimit>(&limit)) {
    const Vec3 axis = b->twist_axis.normalized();
    const Parts p = parts_of(q, axis);
    const double excess = ball_swing(*b, axis, p).excess;
    const double swing_excess = excess <= kJointLimitTolerance ? 0.0 : excess;
    return swing_excess + angle_excess(p.twist, b->min_twist, b->max_twist, p.twist_slack);
  }
  return 0.0;
}

}  // namespace animkit
