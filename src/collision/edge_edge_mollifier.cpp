#include "animkit/collision/edge_edge_mollifier.h"

#include <cassert>

#include "reduced_derivatives.h"

namespace animkit {

namespace {

// c's reduced variables (u, v) from the edges' vertices (reduced_derivatives.h).
Eigen::Matrix<double, 2, 4> mollifier_map() {
  Eigen::Matrix<double, 2, 4> map;
  map << -1, 1, 0, 0,  // u = a1 - a0
      0, 0, -1, 1;     // v = b1 - b0
  return map;
}

}  // namespace

double edge_edge_mollifier_threshold(const Vec3& a0_rest, const Vec3& a1_rest, const Vec3& b0_rest,
                                     const Vec3& b1_rest) {
  return 1e-3 * (a1_rest - a0_rest).squaredNorm() * (b1_rest - b0_rest).squaredNorm();
}

double edge_edge_mollifier(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1,
                           double eps_x) {
  assert(eps_x > 0.0 && "the mollifier threshold must be positive");
  const double c = (a1 - a0).cross(b1 - b0).squaredNorm();
  if (c >= eps_x) return 1.0;
  const double x = c / eps_x;
  return x * (2.0 - x);  // -c^2 / eps_x^2 + 2 c / eps_x
}

StencilDerivatives<4> edge_edge_mollifier_derivatives(const Vec3& a0, const Vec3& a1,
                                                      const Vec3& b0, const Vec3& b1,
                                                      double eps_x) {
  assert(eps_x > 0.0 && "the mollifier threshold must be positive");
  StencilDerivatives<4> out;
  // Most edge pairs are far from parallel, where m = 1: their c alone, not its Hessian.
  if ((a1 - a0).cross(b1 - b0).squaredNorm() >= eps_x) {
    out.value = 1.0;
    return out;
  }
  double c = 0.0;
  collision_detail::ReducedVector<2> grad_c;
  collision_detail::ReducedMatrix<2> hess_c;
  collision_detail::cross_squared_derivatives(a1 - a0, b1 - b0, c, grad_c, hess_c);
  const double x = c / eps_x;
  const double first = 2.0 * (1.0 - x) / eps_x;  // m'(c)
  const double second = -2.0 / (eps_x * eps_x);  // m''(c)
  const collision_detail::ReducedMatrix<2> hess =
      second * grad_c * grad_c.transpose() + first * hess_c;
  return collision_detail::map_to_vertices<2, 4>(x * (2.0 - x), first * grad_c, hess,
                                                 mollifier_map());
}

StencilGradient<4> edge_edge_mollifier_gradient(const Vec3& a0, const Vec3& a1, const Vec3& b0,
                                                const Vec3& b1, double eps_x) {
  assert(eps_x > 0.0 && "the mollifier threshold must be positive");
  StencilGradient<4> out;
  if ((a1 - a0).cross(b1 - b0).squaredNorm() >= eps_x) {
    out.value = 1.0;
    return out;
  }
  double c = 0.0;
  collision_detail::ReducedVector<2> grad_c;
  collision_detail::cross_squared_gradient(a1 - a0, b1 - b0, c, grad_c);
  const double x = c / eps_x;
  const double first = 2.0 * (1.0 - x) / eps_x;  // m'(c)
  return collision_detail::map_gradient_to_vertices<2, 4>(x * (2.0 - x), first * grad_c,
                                                         mollifier_map());
}

}  // namespace animkit
