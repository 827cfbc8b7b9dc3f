#include "animkit/kinematics/euler_angles.h"

#include <cassert>
#include <cmath>

namespace animkit {

namespace {
// Below this, cos(angles[1]) is treated as 0 (gimbal lock): the first and last angles are then
// read from entries that stay well conditioned instead of from two near-zero ones.
constexpr double kGimbalCos = 1e-12;

Vec3 axis(int i) {
  return Vec3::Unit(i);
}
}  // namespace

Quat euler_to_quat(const EulerOrder& order, const Vec3& angles) {
  return Quat(Eigen::AngleAxisd(angles[0], axis(order[0]))) *
         Quat(Eigen::AngleAxisd(angles[1], axis(order[1]))) *
         Quat(Eigen::AngleAxisd(angles[2], axis(order[2])));
}

// With (i, j, k) = order and s = +1 for the cyclic orders (xyz, yzx, zxy), -1 otherwise, the
// matrix R = R_i(a) R_j(b) R_k(c) has (Shoemake, "Euler Angle Conversion", Graphics Gems IV)
//   R[i][k] = s sin b,  R[i][i] = cos b cos c,  R[i][j] = -s cos b sin c,
//   R[k][k] = cos a cos b,  R[j][k] = -s sin a cos b.
// At gimbal lock (cos b = 0) only a + s' c is defined; with c = 0, column j of R is R_i(a) e_j,
// so R[j][j] = cos a and R[k][j] = s sin a.
Vec3 quat_to_euler(const EulerOrder& order, const Quat& q) {
  const int i = order[0], j = order[1], k = order[2];
  assert(i != j && j != k && i != k);
  const double s = ((j - i + 3) % 3 == 1) ? 1.0 : -1.0;
  const Eigen::Matrix3d r = q.normalized().toRotationMatrix();
  const double cos_b = std::hypot(r(i, i), r(i, j));
  const double b = std::atan2(s * r(i, k), cos_b);
  if (cos_b < kGimbalCos) return {std::atan2(s * r(k, j), r(j, j)), b, 0.0};
  return {std::atan2(-s * r(j, k), r(k, k)), b, std::atan2(-s * r(i, j), r(i, i))};
}

}  // namespace animkit
