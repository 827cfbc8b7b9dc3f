#pragma once
// Where a joint limit pushed a joint back, as angular-velocity directions a solver can take out
// of its Jacobian (dls_tree.cpp): the gradients of the limit's active constraints.
#include <array>

#include "animkit/core/types.h"
#include "animkit/kinematics/joint_limits.h"

namespace animkit {

/// Rotation vector (unit axis * angle, angle in [0, pi]) of a unit quaternion, the short way.
Vec3 rotation_vector(const Quat& q);

/// The unit quaternion of a rotation vector.
Quat from_rotation_vector(const Vec3& r);

/// For a ball joint with unit twist axis `a` whose bone points along unit `b` = q a (rest
/// frame), the vector g with d(twist angle)/dt = w . g for angular velocity w (dq/dt = w q / 2).
/// Undefined at b = -a (a half-turn swing, where the twist is); there it returns zero.
Vec3 twist_rate_axis(const Vec3& a, const Vec3& b);

/// The unit axes (parent frame, pointing inward) about which constraining turned the local
/// rotation `local` back from `wanted` (rest: the joint's rest rotation), zero where no push:
/// a ball's swing ([0]) and twist ([1]) separately, another limit's whole correction ([0]).
/// Corrections below kPushThreshold radians are rounding, not pushes.
constexpr double kPushThreshold = 1e-12;
std::array<Vec3, 2> limit_push_axes(const JointLimit& limit, const Quat& rest, const Quat& wanted,
                                    const Quat& local);

/// Whether `local` rests on its limit along the inward axis `inward` (parent frame): turning it
/// outward by kAtLimitAngle radians leaves the limit. False for a zero axis.
constexpr double kAtLimitAngle = 1e-7;
bool at_limit(const JointLimit& limit, const Quat& rest, const Quat& local, const Vec3& inward);

}  // namespace animkit
