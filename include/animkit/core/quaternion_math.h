#pragma once
// Quaternion helpers that stay accurate where the textbook formulas lose precision.
#include <span>

#include "animkit/core/types.h"

namespace animkit {

/// The shortest-arc rotation taking the direction of `from` onto the direction of `to`.
/// Neither vector needs to be normalized; both must be non-zero. Accurate for tiny angles
/// (no "close enough to identity" cut-off, unlike glm::rotation, whose float epsilon makes
/// CCD stall), and for opposite vectors it turns by pi about an axis perpendicular to `from`.
Quat shortest_arc(const Vec3& from, const Vec3& to);

/// A unit vector perpendicular to the non-zero `v`, chosen deterministically (crossed with the
/// coordinate axis least aligned with `v`, so the result is well conditioned).
Vec3 perpendicular_axis(const Vec3& v);

/// Angle in radians, in [0, pi], of the rotation that takes `a` to `b` (sign of q ignored).
double rotation_angle_between(const Quat& a, const Quat& b);

/// The largest rotation_angle_between(before[i], after[i]) over two equally long lists of
/// joint rotations (0 when empty): the "jitter" of a pose change, as the drawing sessions report.
double largest_rotation_change(std::span<const Quat> before, std::span<const Quat> after);

}  // namespace animkit
