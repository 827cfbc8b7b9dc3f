#pragma once
// The analytic two-bone solver for a limb (hip-knee-ankle, shoulder-elbow-wrist):
// the law of cosines places the middle joint in the plane of the root, the target and a pole
// target (where the knee or elbow should point), on the pole's side. Pure math on world
// positions; the caller applies the two rotations to its skeleton (and may constrain them
// with joint_limits.h).
#include <optional>

#include "animkit/core/result.h"
#include "animkit/core/types.h"

namespace animkit {

/// The limb as it is now, and where it should go. All positions world space, scene units.
struct TwoBoneInput {
  Vec3 root = Vec3::Zero();      ///< the upper bone's joint (hip, shoulder); it stays put
  Vec3 middle = Vec3::UnitX();   ///< the joint between the bones (knee, elbow)
  Vec3 end = 2 * Vec3::UnitX();  ///< the lower bone's far joint (ankle, wrist)
  Vec3 target = Vec3::Zero();    ///< where `end` should go
  Vec3 pole = Vec3::UnitY();     ///< a point the middle joint should bend toward

  /// The first problem ("two-bone upper bone (root to middle) has zero length"), or nothing.
  std::optional<Error> validate() const;
};

/// Settings of solve_two_bone().
struct TwoBoneSettings {
  /// Scene units. A target nearer the root than this has no direction, and a pole nearer the
  /// root-target line than this gives no bend side; the solver then keeps the limb's current
  /// direction / bend plane instead. Default 1e-9; must be positive.
  double degenerate_length = 1e-9;

  /// The first problem (a degenerate_length that is not positive and finite), or nothing.
  std::optional<Error> validate() const;
};

/// The solved limb: the two rotations to apply, the new joint positions, and how near the end
/// came to the target.
struct TwoBoneResult {
  /// World-space rotation to apply to the upper bone about the root: the new root->middle
  /// vector is upper_rotation * (middle - root). Unit.
  Quat upper_rotation = Quat::Identity();
  /// World-space rotation taking the old lower bone to the new one (not relative to the upper
  /// rotation): the new middle->end vector is lower_rotation * (end - middle). Unit. Both
  /// rotations map the old bend plane's normal to the new one's, so the bend between the bones
  /// stays a rotation about that normal (a knee stays a hinge).
  Quat lower_rotation = Quat::Identity();
  Vec3 middle = Vec3::Zero();  ///< new world position of the middle joint
  Vec3 end = Vec3::Zero();     ///< new world position of the end joint
  /// |target - root| is within [|l1 - l2|, l1 + l2]: the end reaches the target. Otherwise the
  /// limb lies straight along the root->target line (stretched or folded), its end as near the
  /// target as the bones allow.
  bool reached = false;
  double error = 0.0;  ///< |end - target|, scene units
};

/// Solves the limb. Fails only on invalid input or settings (the error names the problem).
/// Deterministic and allocation-free on success.
Result<TwoBoneResult> solve_two_bone(const TwoBoneInput& input,
                                     const TwoBoneSettings& settings = {});

}  // namespace animkit
