#pragma once
// Internal building blocks of the distance and mollifier derivatives (distance.cpp,
// edge_edge_mollifier.cpp): functions of K reduced 3-vectors z = (z_0, ..., z_{K-1}) that are
// fixed differences of a stencil's vertices, z = J x with J = C (x) I_3 for a K x V matrix C of
// small integers. Then grad_x = J^T grad_z and hess_x = J^T hess_z J, exactly (J is constant).
#include <Eigen/Core>

#include "animkit/collision/distance.h"

namespace animkit::collision_detail {

template <int K>
using ReducedVector = Eigen::Matrix<double, 3 * K, 1>;
template <int K>
using ReducedMatrix = Eigen::Matrix<double, 3 * K, 3 * K>;

/// [a]_x, the matrix of a x (.).
inline Eigen::Matrix3d cross_matrix(const Vec3& a) {
  Eigen::Matrix3d m;
  m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return m;
}

/// f = N / D from the derivatives of N and D (D > 0):
///   grad f = (grad N - f grad D) / D
///   hess f = (hess N - f hess D - grad D grad f^T - grad f grad D^T) / D
/// (differentiate D grad f = grad N - f grad D once more).
template <int K>
void quotient_rule_gradient(double n, const ReducedVector<K>& grad_n, double d,
                            const ReducedVector<K>& grad_d, double& f, ReducedVector<K>& grad_f) {
  f = n / d;
  grad_f = (grad_n - f * grad_d) / d;
}
template <int K>
void quotient_rule(double n, const ReducedVector<K>& grad_n, const ReducedMatrix<K>& hess_n,
                   double d, const ReducedVector<K>& grad_d, const ReducedMatrix<K>& hess_d,
                   double& f, ReducedVector<K>& grad_f, ReducedMatrix<K>& hess_f) {
  quotient_rule_gradient<K>(n, grad_n, d, grad_d, f, grad_f);
  hess_f = (hess_n - f * hess_d - grad_d * grad_f.transpose() - grad_f * grad_d.transpose()) / d;
}

/// Maps derivatives in the reduced variables to the V stencil vertices: z_k = sum_j C(k, j) x_j,
/// so grad_x[j] = sum_k C(k, j) grad_z[k] and hess_x[i][j] = sum_kl C(k, i) C(l, j) hess_z[k][l]
/// (3x3 blocks; J is never formed, it is mostly zeros).
template <int K, int V>
StencilGradient<V> map_gradient_to_vertices(double value, const ReducedVector<K>& grad,
                                            const Eigen::Matrix<double, K, V>& coefficients) {
  StencilGradient<V> out;
  out.value = value;
  for (int j = 0; j < V; ++j) {
    for (int k = 0; k < K; ++k) {
      if (coefficients(k, j) != 0.0) {
        out.gradient.template segment<3>(3 * j) +=
            coefficients(k, j) * grad.template segment<3>(3 * k);
      }
    }
  }
  return out;
}
template <int K, int V>
StencilDerivatives<V> map_to_vertices(double value, const ReducedVector<K>& grad,
                                      const ReducedMatrix<K>& hess,
                                      const Eigen::Matrix<double, K, V>& coefficients) {
  StencilDerivatives<V> out;
  const StencilGradient<V> first = map_gradient_to_vertices<K, V>(value, grad, coefficients);
  out.value = first.value;
  out.gradient = first.gradient;
  for (int j = 0; j < V; ++j) {
    for (int k = 0; k < K; ++k) {
      if (coefficients(k, j) == 0.0) continue;
      for (int i = 0; i < V; ++i) {
        for (int l = 0; l < K; ++l) {
          const double weight = coefficients(k, j) * coefficients(l, i);
          if (weight == 0.0) continue;
          out.hessian.template block<3, 3>(3 * i, 3 * j) +=
              weight * hess.template block<3, 3>(3 * l, 3 * k);
        }
      }
    }
  }
  return out;
}

/// c = |u x v|^2 with its gradient and Hessian in (u, v). With n = u x v, the Jacobian is
/// dn/d(u, v) = [-[v]_x, [u]_x], so grad c = 2 J_n^T n and
///   hess c = 2 J_n^T J_n + 2 sum_k n_k hess n_k,
/// where sum_k n_k hess n_k is the Hessian of the triple product w . (u x v) at fixed w = n:
/// zero diagonal blocks, (u, v) block -[n]_x, (v, u) block [n]_x.
inline Eigen::Matrix<double, 3, 6> cross_jacobian(const Vec3& u, const Vec3& v) {
  Eigen::Matrix<double, 3, 6> jacobian;
  jacobian << -cross_matrix(v), cross_matrix(u);
  return jacobian;
}
inline void cross_squared_gradient(const Vec3& u, const Vec3& v, double& c,
                                   ReducedVector<2>& grad) {
  const Vec3 n = u.cross(v);
  c = n.squaredNorm();
  grad = 2.0 * cross_jacobian(u, v).transpose() * n;
}
inline void cross_squared_derivatives(const Vec3& u, const Vec3& v, double& c,
                                      ReducedVector<2>& grad, ReducedMatrix<2>& hess) {
  cross_squared_gradient(u, v, c, grad);
  const Vec3 n = u.cross(v);
  const Eigen::Matrix<double, 3, 6> jacobian = cross_jacobian(u, v);
  hess = 2.0 * jacobian.transpose() * jacobian;
  const Eigen::Matrix3d n_cross = cross_matrix(n);
  hess.block<3, 3>(0, 3) -= 2.0 * n_cross;
  hess.block<3, 3>(3, 0) += 2.0 * n_cross;
}

}  // namespace animkit::collision_detail
