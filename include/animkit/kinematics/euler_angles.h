#pragma once
// Euler angles about three distinct axes (Tait-Bryan), as BVH files store rotations: for the
// order (a, b, c) the rotation is R_a(angle[0]) * R_b(angle[1]) * R_c(angle[2]), i.e. applied to
// a vector c first, a last (intrinsic a, b, c). All 6 orders are supported.
#include <array>

#include "animkit/core/types.h"

namespace animkit {

/// The axes in composition order: 0 = x, 1 = y, 2 = z; a permutation of {0, 1, 2}.
using EulerOrder = std::array<int, 3>;

/// R_order[0](angles[0]) * R_order[1](angles[1]) * R_order[2](angles[2]); angles in radians.
Quat euler_to_quat(const EulerOrder& order, const Vec3& angles);

/// The angles (radians) with euler_to_quat(order, angles) == q: angles[1] in [-pi/2, pi/2],
/// the others in [-pi, pi]. At gimbal lock (|angles[1]| = pi/2, where only angles[0] +-
/// angles[2] is defined) angles[2] is 0 and angles[0] carries the whole turn; never NaN.
Vec3 quat_to_euler(const EulerOrder& order, const Quat& q);

}  // namespace animkit
