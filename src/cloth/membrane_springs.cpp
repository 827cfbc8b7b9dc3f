#include "membrane_springs.h"

#include <Eigen/Dense>
#include <algorithm>

namespace animkit {

std::array<double, 3> membrane_spring_stiffness(const std::array<Vec3, 3>& x,
                                                const ClothMaterial& material, const Vec3& warp) {
  const Vec3 cross = (x[1] - x[0]).cross(x[2] - x[0]);
  const double area = 0.5 * cross.norm();
  const Vec3 normal = cross.normalized();
  // The material frame in the triangle's plane.
  Vec3 w = warp - warp.dot(normal) * normal;
  if (w.squaredNorm() < 1e-12 * warp.squaredNorm()) w = x[1] - x[0];
  w.normalize();
  const Vec3 f = normal.cross(w);
  // Dynamic sizes: GCC 12 reports a false out-of-bounds read in the fixed 3 x 3 solve.
  Eigen::MatrixXd system(3, 3);
  std::array<double, 3> length2{};
  for (int e = 0; e < 3; ++e) {
    const Vec3 d = x[(e + 1) % 3] - x[e];
    length2[e] = d.squaredNorm();
    const double c = d.dot(w) / d.norm(), s = d.dot(f) / d.norm();
    system(0, e) = c * c * c * c;
    system(1, e) = s * s * s * s;
    system(2, e) = c * c * s * s;
  }
  Eigen::VectorXd target(3);
  target << material.stretch, material.stretch, material.shear;
  // Rank decided relative to the largest entry (they are at most 1): an equilateral triangle's
  // two look-alike columns differ by rounding only.
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> solver;
  solver.setThreshold(1e-9);
  solver.compute(system);
  const Eigen::VectorXd kappa = solver.solve(target);
  std::array<double, 3> k{};
  for (int e = 0; e < 3; ++e) k[e] = std::max(kappa[e], 0.0) * area / length2[e];
  return k;
}

}  // namespace animkit
