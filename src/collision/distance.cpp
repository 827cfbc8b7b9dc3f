#include "animkit/collision/distance.h"

#include <cassert>

#include "reduced_derivatives.h"

namespace animkit {

using collision_detail::cross_matrix;
using collision_detail::cross_squared_derivatives;
using collision_detail::cross_squared_gradient;
using collision_detail::map_gradient_to_vertices;
using collision_detail::map_to_vertices;
using collision_detail::quotient_rule;
using collision_detail::quotient_rule_gradient;
using collision_detail::ReducedMatrix;
using collision_detail::ReducedVector;

namespace {

// f(e, u, v) = s^2 / |u x v|^2 with s = e . (u x v) = det[e, u, v], in z = (e, u, v):
//   grad s = (u x v, v x e, e x u)
//   hess s: zero diagonal blocks; (e,u) = -[v]_x, (e,v) = [u]_x, (u,v) = -[e]_x and the
//           transposed blocks below (d(u x v)/du = -[v]_x, d(u x v)/dv = [u]_x, d(v x e)/dv
//           = -[e]_x)
//   N = s^2: grad N = 2 s grad s, hess N = 2 grad s grad s^T + 2 s hess s
//   D = |u x v|^2: cross_squared_derivatives in the (u, v) slots
// and the quotient rule. Shared by point-plane and line-line, which differ only in J.
ReducedVector<3> triple_product_gradient(const Vec3& e, const Vec3& u, const Vec3& v,
                                         const Vec3& n) {
  ReducedVector<3> grad_s;
  grad_s.segment<3>(0) = n;
  grad_s.segment<3>(3) = v.cross(e);
  grad_s.segment<3>(6) = e.cross(u);
  return grad_s;
}

// The plane form's value and gradient alone: the first halves of the steps below.
void plane_form_gradient(const Vec3& e, const Vec3& u, const Vec3& v, double& f,
                         ReducedVector<3>& grad) {
  const Vec3 n = u.cross(v);
  const double s = e.dot(n);
  const ReducedVector<3> grad_n = 2.0 * s * triple_product_gradient(e, u, v, n);
  double d = 0.0;
  ReducedVector<2> grad_uv;
  cross_squared_gradient(u, v, d, grad_uv);
  assert(d > 0.0 && "plane form needs u x v != 0");
  ReducedVector<3> grad_d = ReducedVector<3>::Zero();
  grad_d.tail<6>() = grad_uv;
  quotient_rule_gradient<3>(s * s, grad_n, d, grad_d, f, grad);
}

void plane_form_derivatives(const Vec3& e, const Vec3& u, const Vec3& v, double& f,
                            ReducedVector<3>& grad, ReducedMatrix<3>& hess) {
  const Vec3 n = u.cross(v);
  const double s = e.dot(n);
  const ReducedVector<3> grad_s = triple_product_gradient(e, u, v, n);
  ReducedMatrix<3> hess_s = ReducedMatrix<3>::Zero();
  hess_s.block<3, 3>(0, 3) = -cross_matrix(v);
  hess_s.block<3, 3>(0, 6) = cross_matrix(u);
  hess_s.block<3, 3>(3, 6) = -cross_matrix(e);
  hess_s.block<3, 3>(3, 0) = cross_matrix(v);
  hess_s.block<3, 3>(6, 0) = -cross_matrix(u);
  hess_s.block<3, 3>(6, 3) = cross_matrix(e);
  const ReducedVector<3> grad_n = 2.0 * s * grad_s;
  const ReducedMatrix<3> hess_n = 2.0 * grad_s * grad_s.transpose() + 2.0 * s * hess_s;

  double d = 0.0;
  ReducedVector<2> grad_uv;
  ReducedMatrix<2> hess_uv;
  cross_squared_derivatives(u, v, d, grad_uv, hess_uv);
  assert(d > 0.0 && "plane form needs u x v != 0");
  ReducedVector<3> grad_d = ReducedVector<3>::Zero();
  ReducedMatrix<3> hess_d = ReducedMatrix<3>::Zero();
  grad_d.tail<6>() = grad_uv;
  hess_d.bottomRightCorner<6, 6>() = hess_uv;
  quotient_rule<3>(s * s, grad_n, hess_n, d, grad_d, hess_d, f, grad, hess);
}

// The reduced variables' maps J = C (x) I_3 (reduced_derivatives.h), one row per variable.
Eigen::Matrix<double, 2, 3> point_line_map() {
  Eigen::Matrix<double, 2, 3> c;
  c << 1, -1, 0,  // e = p - a
      0, -1, 1;   // u = b - a
  return c;
}
Eigen::Matrix<double, 3, 4> point_plane_map() {
  Eigen::Matrix<double, 3, 4> map;
  map << 1, -1, 0, 0,  // e = p - a
      0, -1, 1, 0,     // u = b - a
      0, -1, 0, 1;     // v = c - a
  return map;
}
Eigen::Matrix<double, 3, 4> line_line_map() {
  Eigen::Matrix<double, 3, 4> map;
  map << 1, 0, -1, 0,  // e = a0 - b0
      -1, 1, 0, 0,     // u = a1 - a0
      0, 0, -1, 1;     // v = b1 - b0
  return map;
}

double plane_form(const Vec3& e, const Vec3& u, const Vec3& v) {
  const Vec3 n = u.cross(v);
  const double d = n.squaredNorm();
  assert(d > 0.0 && "plane form needs u x v != 0");
  const double s = e.dot(n);
  return s * s / d;
}

}  // namespace

double point_point_distance_squared(const Vec3& p, const Vec3& q) {
  return (p - q).squaredNorm();
}

// f = |p - q|^2: grad = (2 e, -2 e) with e = p - q, hess = 2 [I -I; -I I].
StencilDerivatives<2> point_point_distance_squared_derivatives(const Vec3& p, const Vec3& q) {
  const Vec3 e = p - q;
  StencilDerivatives<2> out;
  out.value = e.squaredNorm();
  out.gradient << 2.0 * e, -2.0 * e;
  out.hessian.diagonal().setConstant(2.0);
  out.hessian.block<3, 3>(0, 3).diagonal().setConstant(-2.0);
  out.hessian.block<3, 3>(3, 0).diagonal().setConstant(-2.0);
  return out;
}

StencilGradient<2> point_point_distance_squared_gradient(const Vec3& p, const Vec3& q) {
  const Vec3 e = p - q;
  StencilGradient<2> out;
  out.value = e.squaredNorm();
  out.gradient << 2.0 * e, -2.0 * e;
  return out;
}

double point_line_distance_squared(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 e = p - a, u = b - a;
  const double d = u.squaredNorm();
  assert(d > 0.0 && "point-line needs a != b");
  // |e x u|^2 / |u|^2 rather than |e|^2 - (e . u)^2 / |u|^2: no cancellation when p is close
  // to the line, which is where the barrier reads the distance.
  return e.cross(u).squaredNorm() / d;
}

// f(e, u) = N / D with N = |e x u|^2 and D = |u|^2, z = (e, u) = (p - a, b - a):
//   N is cross_squared_derivatives(e, u); grad D = (0, 2 u), hess D = diag(0, 2 I);
//   then the quotient rule.
StencilDerivatives<3> point_line_distance_squared_derivatives(const Vec3& p, const Vec3& a,
                                                              const Vec3& b) {
  const Vec3 e = p - a, u = b - a;
  double n = 0.0;
  ReducedVector<2> grad_n;
  ReducedMatrix<2> hess_n;
  cross_squared_derivatives(e, u, n, grad_n, hess_n);
  const double d = u.squaredNorm();
  assert(d > 0.0 && "point-line needs a != b");
  ReducedVector<2> grad_d = ReducedVector<2>::Zero();
  grad_d.segment<3>(3) = 2.0 * u;
  ReducedMatrix<2> hess_d = ReducedMatrix<2>::Zero();
  hess_d.bottomRightCorner<3, 3>().diagonal().setConstant(2.0);
  double f = 0.0;
  ReducedVector<2> grad;
  ReducedMatrix<2> hess;
  quotient_rule<2>(n, grad_n, hess_n, d, grad_d, hess_d, f, grad, hess);
  return map_to_vertices<2, 3>(f, grad, hess, point_line_map());
}

StencilGradient<3> point_line_distance_squared_gradient(const Vec3& p, const Vec3& a,
                                                        const Vec3& b) {
  const Vec3 e = p - a, u = b - a;
  double n = 0.0;
  ReducedVector<2> grad_n;
  cross_squared_gradient(e, u, n, grad_n);
  const double d = u.squaredNorm();
  assert(d > 0.0 && "point-line needs a != b");
  ReducedVector<2> grad_d = ReducedVector<2>::Zero();
  grad_d.segment<3>(3) = 2.0 * u;
  double f = 0.0;
  ReducedVector<2> grad;
  quotient_rule_gradient<2>(n, grad_n, d, grad_d, f, grad);
  return map_gradient_to_vertices<2, 3>(f, grad, point_line_map());
}

double point_plane_distance_squared(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  return plane_form(p - a, b - a, c - a);
}

StencilDerivatives<4> point_plane_distance_squared_derivatives(const Vec3& p, const Vec3& a,
                                                               const Vec3& b, const Vec3& c) {
  double f = 0.0;
  ReducedVector<3> grad;
  ReducedMatrix<3> hess;
  plane_form_derivatives(p - a, b - a, c - a, f, grad, hess);
  return map_to_vertices<3, 4>(f, grad, hess, point_plane_map());
}

StencilGradient<4> point_plane_distance_squared_gradient(const Vec3& p, const Vec3& a,
                                                         const Vec3& b, const Vec3& c) {
  double f = 0.0;
  ReducedVector<3> grad;
  plane_form_gradient(p - a, b - a, c - a, f, grad);
  return map_gradient_to_vertices<3, 4>(f, grad, point_plane_map());
}

// The distance between two lines is the distance of a0 to the plane through b0 spanned by the
// two directions: the plane form with e = a0 - b0, u = a1 - a0, v = b1 - b0.
double line_line_distance_squared(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
  return plane_form(a0 - b0, a1 - a0, b1 - b0);
}

StencilDerivatives<4> line_line_distance_squared_derivatives(const Vec3& a0, const Vec3& a1,
                                                             const Vec3& b0, const Vec3& b1) {
  double f = 0.0;
  ReducedVector<3> grad;
  ReducedMatrix<3> hess;
  plane_form_derivatives(a0 - b0, a1 - a0, b1 - b0, f, grad, hess);
  return map_to_vertices<3, 4>(f, grad, hess, line_line_map());
}

StencilGradient<4> line_line_distance_squared_gradient(const Vec3& a0, const Vec3& a1,
                                                       const Vec3& b0, const Vec3& b1) {
  double f = 0.0;
  ReducedVector<3> grad;
  plane_form_gradient(a0 - b0, a1 - a0, b1 - b0, f, grad);
  return map_gradient_to_vertices<3, 4>(f, grad, line_line_map());
}

}  // namespace animkit
