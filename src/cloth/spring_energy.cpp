#include "animkit/cloth/spring_energy.h"

#include <algorithm>
#include <cmath>

namespace animkit {

double spring_energy(const Vec3& x_a, const Vec3& x_b, double stiffness, double rest_length) {
  const double stretch = (x_a - x_b).norm() - rest_length;
  return 0.5 * stiffness * stretch * stretch;
}

Vec3 spring_gradient(const Vec3& x_a, const Vec3& x_b, double stiffness, double rest_length) {
  const Vec3 d = x_a - x_b;
  const double length = d.norm();
  if (length == 0.0) return Vec3::Zero();  // direction undefined; E is not differentiable here
  return (stiffness * (length - rest_length) / length) * d;
}

Mat3 spring_hessian_block(const Vec3& x_a, const Vec3& x_b, double stiffness, double rest_length,
                          bool projected) {
  const Vec3 d = x_a - x_b;
  const double length = d.norm();
  // Coincident particles: no direction; the clamped transverse term is 0 and the axial one
  // has no axis, so the best PSD stand-in is the isotropic k I (what u u^T averages to x3).
  if (length == 0.0) return Mat3::Identity() * stiffness;
  const Vec3 u = d / length;
  const Mat3 uu = u * u.transpose();
  double transverse = 1.0 - rest_length / length;
  if (projected) transverse = std::max(transverse, 0.0);
  return stiffness * (uu + transverse * (Mat3::Identity() - uu));
}

}  // namespace animkit
