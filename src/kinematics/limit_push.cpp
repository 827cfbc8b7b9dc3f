#include "limit_push.h"

#include <cmath>
#include <variant>

namespace animkit {

// Rotation vector (axis * angle, angle in [0, pi]) of a unit quaternion, the short way round.
Vec3 rotation_vector(const Quat& q) {
  const double sign = q.w() < 0.0 ? -1.0 : 1.0;
  const Vec3 v = sign * q.vec();
  const double s = v.norm();
  if (s < 1e-300) return 2.0 * v;  // angle ~ 2 s: the first-order limit, exact at zero
  return (2.0 * std::atan2(s, sign * q.w()) / s) * v;
}

Quat from_rotation_vector(const Vec3& r) {
  const double angle = r.norm();
  if (angle < 1e-300) return Quat::Identity();
  const Vec3 v = (std::sin(0.5 * angle) / angle) * r;
  return Quat(std::cos(0.5 * angle), v.x(), v.y(), v.z());
}

// q = s(b) t with s the shortest arc a -> b and t a twist about a: the angular velocity splits
// as w = w_s + (dtwist/dt) b, and the shortest arc spins about b at (a x b) . db/dt / (1 + a.b)
// times -1; with db/dt = w x b this gives dtwist/dt = w . (b + (a - (a.b) b) / (1 + a.b)).
// (Check: w = b is a pure twist, rate 1; w = a x b moves b along the arc, rate 0.)
Vec3 twist_rate_axis(const Vec3& a, const Vec3& b) {
  const double c = a.dot(b);
  if (c <= -1.0 + 1e-9) return Vec3::Zero();
  return b + (a - c * b) / (1.0 + c);
}

// The axes (parent frame, pointing inward) about which constraining turned `local` back from
// `wanted`: the gradients, in angular velocity, of the limit's active constraints. A ball's
// swing and twist are separate, so a joint in a corner of its limit is blocked in both. In the
// rest frame (q = rest^-1 L, angular velocity w with dq/dt = w q / 2, twist axis a, bone
// b = q a = swing a):
//   swing angle: d(swing)/dt = w . (a x b) / |a x b|, the axis of the swing correction;
//   twist angle: q = s(b) t with s the shortest arc a -> b, so w = w_s + (dtwist/dt) b, and the
//   shortest arc's own spin about b gives dtwist/dt = w . (b + (a - (a.b) b) / (1 + a.b)).
// Turning a bone by w perpendicular to it therefore changes its twist too; blocking only
// rotations about the bone lets the twist run into its limit again every iteration. Other
// limits: the whole correction's axis. All mapped to the parent frame by `rest`.
std::array<Vec3, 2> limit_push_axes(const JointLimit& limit, const Quat& rest, const Quat& wanted,
                                    const Quat& local) {
  std::array<Vec3, 2> axes{Vec3::Zero(), Vec3::Zero()};
  // Corrections below rounding size are no push (their axes would be noise).
  auto unit = [](const Vec3& v) {
    return v.norm() > kPushThreshold ? Vec3(v.normalized()) : Vec3::Zero();
  };
  if (const auto* ball = std::get_if<BallLimit>(&limit)) {
    const Vec3 a = ball->twist_axis.normalized();
    const SwingTwist w = swing_twist(rest.conjugate() * wanted, a);
    const SwingTwist c = swing_twist(rest.conjugate() * local, a);
    axes[0] = unit(rest * rotation_vector(c.swing * w.swing.conjugate()));
    const double delta = rotation_vector(c.twist * w.twist.conjugate()).dot(a);
    if (std::abs(delta) > kPushThreshold)
      axes[1] = (delta > 0.0 ? 1.0 : -1.0) * unit(rest * twist_rate_axis(a, c.swing * a));
    return axes;
  }
  axes[0] = unit(rotation_vector(local * wanted.conjugate()));
  return axes;
}

bool at_limit(const JointLimit& limit, const Quat& rest, const Quat& local, const Vec3& inward) {
  if (inward.isZero()) return false;
  const Quat out = from_rotation_vector(-kAtLimitAngle * inward) * local;
  return violation(limit, rest.conjugate() * out) > 0.0;
}

}  // namespace animkit
