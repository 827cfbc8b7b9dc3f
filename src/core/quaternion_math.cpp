#include "animkit/core/quaternion_math.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace animkit {

Quat shortest_arc(const Vec3& from, const Vec3& to) {
  // For unit a, b the half-way quaternion is normalize(1 + a.b, a x b). Scaling by |from||to|
  // gives normalize(|from||to| + from.to, from x to): one square root fewer and no
  // normalization of the inputs. For small angles the vector part stays exact, so the rotation
  // never collapses to identity before the directions really agree.
  const double norms = std::sqrt(from.squaredNorm() * to.squaredNorm());
  const double w = norms + from.dot(to);
  // w = |from||to| (1 + cos angle) is computed with an absolute rounding error of a few eps
  // |from||to|; only below that are the directions indistinguishable from opposite.
  if (w <= 4.0 * std::numeric_limits<double>::epsilon() * norms) {
    // Opposite directions: rotate by pi about an axis perpendicular to `from`.
    const Vec3 axis = perpendicular_axis(from);
    return Quat(0.0, axis.x(), axis.y(), axis.z());
  }
  const Vec3 v = from.cross(to);
  Quat q(w, v.x(), v.y(), v.z());
  q.normalize();
  return q;
}

Vec3 perpendicular_axis(const Vec3& v) {
  const Vec3 a = v.cwiseAbs();
  const Vec3 helper = (a.x() <= a.y() && a.x() <= a.z()) ? Vec3::UnitX()
                      : (a.y() <= a.z())                 ? Vec3::UnitY()
                                                         : Vec3::UnitZ();
  return v.cross(helper).normalized();
}

double rotation_angle_between(const Quat& a, const Quat& b) {
  const Quat d = a.conjugate() * b;
  // atan2 form: accurate for small and large angles alike, no acos domain issues.
  return 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

double largest_rotation_change(std::span<const Quat> before, std::span<const Quat> after) {
  assert(before.size() == after.size());
  double largest = 0.0;
  for (std::size_t j = 0; j < before.size(); ++j) {
    largest = std::max(largest, rotation_angle_between(before[j], after[j]));
  }
  return largest;
}

}  // namespace animkit
