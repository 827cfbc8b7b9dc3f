#pragma once
// Joint limits as standalone math on a joint's local rotation relative to its rest
// rotation: hinge joints (one axis, an angle range) and ball joints (a swing cone about the
// bone plus a twist range about it), by the swing-twist decomposition q = swing * twist.
// Solvers call constrain() inside their iterations; nothing here knows about skeletons.
#include <optional>
#include <variant>

#include "animkit/core/result.h"
#include "animkit/core/types.h"

namespace animkit {

/// Angles within this many radians beyond a limit count as inside it, so that a constrained
/// rotation (whose angles carry rounding) is inside and constrain() is idempotent. A ball's
/// twist gets more slack near a half-turn swing, where its angle is ill-conditioned (rounding
/// moves it by about 16 eps / cos(swing / 2) radians; at exactly a half turn it is undefined).
constexpr double kJointLimitTolerance = 1e-12;

/// No limit: every rotation is allowed.
struct FreeJoint {};

/// One rotational degree of freedom: rotations about `axis` by an angle in [min_angle,
/// max_angle] (right-handed about the axis).
struct HingeLimit {
  Vec3 axis = Vec3::UnitZ();  ///< joint's rest frame, unit length
  double min_angle = 0.0;     ///< radians, in [-pi, pi], at most max_angle
  double max_angle = 0.0;     ///< radians, in [-pi, pi]

  /// The first problem ("hinge axis is not unit length (norm 2)"), or nothing.
  std::optional<Error> validate() const;
};

/// A ball joint: the bone (along `twist_axis` at rest) may swing away from its rest direction
/// within a cone and twist about itself within [min_twist, max_twist]. The cone is circular,
/// of half-angle `swing_angle`, unless `swing_angle_2` is set. Then it is elliptical in the
/// swing's rotation vector r (the swing's axis times its angle, perpendicular to twist_axis):
///   (r . swing_axis / swing_angle)^2 + (r . (twist_axis x swing_axis) / swing_angle_2)^2 <= 1,
/// i.e. swings about `swing_axis` reach swing_angle, swings about the third axis swing_angle_2.
struct BallLimit {
  Vec3 twist_axis = Vec3::UnitY();  ///< the bone's direction in the joint's rest frame, unit
  double swing_angle = 0.0;         ///< cone half-angle, radians, in [0, pi]
  double min_twist = 0.0;           ///< radians, in [-pi, pi], at most max_twist
  double max_twist = 0.0;           ///< radians, in [-pi, pi]
  /// Elliptical cones only: the swing rotation axis whose half-angle is swing_angle; joint's
  /// rest frame, unit, perpendicular to twist_axis.
  Vec3 swing_axis = Vec3::UnitX();
  /// Elliptical cones only: half-angle of swings about twist_axis x swing_axis, radians, in
  /// [0, pi]. Unset (the default): a circular cone.
  std::optional<double> swing_angle_2 = std::nullopt;

  /// The first problem ("ball twist axis is not unit length (norm 2)"): a non-finite or non-unit
  /// axis, a cone angle outside [0, pi], a swing axis not perpendicular to the twist axis (checked
  /// only for an elliptical cone), a twist range that is non-finite, outside [-pi, pi] or with
  /// min_twist > max_twist; or nothing.
  std::optional<Error> validate() const;
};

using JointLimit = std::variant<FreeJoint, HingeLimit, BallLimit>;

/// validate() of whichever limit `limit` holds (a FreeJoint is always valid).
std::optional<Error> validate(const JointLimit& limit);

/// q = swing * twist: `twist` a rotation about `axis`, `swing` about an axis perpendicular to
/// it. Both unit, both with w >= 0 (so swing's angle is in [0, pi], twist's in [-pi, pi]).
struct SwingTwist {
  Quat swing;  ///< about an axis perpendicular to `axis`; unit, w >= 0, angle in [0, pi]
  Quat twist;  ///< about `axis`; unit, w >= 0, angle in [-pi, pi]
};

/// Swing-twist decomposition of the unit `q` about the unit `axis`. q and -q give the same
/// result. At a swing of exactly pi (q's projection on the twist subspace is zero) the twist is
/// undefined and taken as the identity.
SwingTwist swing_twist(const Quat& q, const Vec3& axis);

/// Signed angle in [-pi, pi] of a rotation `twist` about the unit `axis` (right-handed).
double twist_angle(const Quat& twist, const Vec3& axis);

/// The rotation inside `limit` nearest to the unit `q`; q itself (bit for bit) when inside.
/// Hinge: the exact nearest rotation about the axis with an angle in range, nearest by the
/// angle of the rotation between them (project onto rotations about the axis, which is q's
/// twist, then clamp its angle the short way round the circle).
/// Ball: the swing is clamped to the cone and the twist (the short way round) to its range.
/// Circular cone: the swing is shortened along its own axis, which puts the bone at the
/// direction inside the cone nearest to q's bone direction (geodesic distance). Elliptical
/// cone: the swing's rotation vector goes to the nearest point of the ellipse (Euclidean in
/// rotation vectors, which measure the bone's geodesic distance from rest exactly only along
/// rays from the rest direction). Either way this is not always the nearest rotation overall
/// (swing and twist trade off), but q is within swing excess + twist excess of it.
/// Results are unit, idempotent, and never NaN for unit input.
Quat constrain(const JointLimit& limit, const Quat& q);

/// How far the unit `q` is beyond `limit`, in radians; 0 inside (as constrain() decides).
/// Hinge: the angle of the rotation from q to constrain(q) (the exact distance to the limit).
/// Ball: swing excess (the angle beyond a circular cone; for an elliptical one the distance of
/// the swing's rotation vector to the ellipse) + twist excess (an upper bound on the distance).
double violation(const JointLimit& limit, const Quat& q);

}  // namespace animkit
