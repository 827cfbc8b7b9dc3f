#include "mesh_bending.h"

namespace animkit {

namespace {
// cot of the angle at p of the triangle (p, q, r).
double cot_at(const Vec3& p, const Vec3& q, const Vec3& r) {
  const Vec3 u = q - p, v = r - p;
  return u.dot(v) / u.cross(v).norm();
}
}  // namespace

EdgeBend edge_bend(const std::array<Vec3, 4>& x, double bending) {
  const double alpha0 = cot_at(x[0], x[1], x[2]), alpha1 = cot_at(x[1], x[0], x[2]);
  const double beta0 = cot_at(x[0], x[1], x[3]), beta1 = cot_at(x[1], x[0], x[3]);
  const double area0 = 0.5 * (x[1] - x[0]).cross(x[2] - x[0]).norm();
  const double area1 = 0.5 * (x[1] - x[0]).cross(x[3] - x[0]).norm();
  EdgeBend bend;
  bend.weights = {alpha1 + beta1, alpha0 + beta0, -(alpha0 + alpha1), -(beta0 + beta1)};
  bend.stiffness = bending / (area0 + area1);
  return bend;
}

}  // namespace animkit
