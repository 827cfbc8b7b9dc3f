#include "friction_pair.h"

#include <algorithm>
#include <cmath>

#include "animkit/collision/closest_points.h"

namespace animkit {

namespace {

// An orthonormal basis of the plane normal to the unit vector n: n x e_k for the axis e_k
// least aligned with n (never parallel to it), then n x that.
Eigen::Matrix<double, 3, 2> tangent_basis(const Vec3& n) {
  int k = 0;
  n.cwiseAbs().minCoeff(&k);
  const Vec3 t1 = n.cross(Vec3::Unit(k)).normalized();
  Eigen::Matrix<double, 3, 2> basis;
  basis.col(0) = t1;
  basis.col(1) = n.cross(t1);
  return basis;
}

}  // namespace

double friction_f0(double y, double eps) {
  if (y >= eps) return y;
  return y * y * (1.0 / eps - y / (3.0 * eps * eps)) + eps / 3.0;
}

double friction_f1(double y, double eps) {
  if (y >= eps) return 1.0;
  return y * (2.0 / eps - y / (eps * eps));
}

double friction_f1_over_y(double y, double eps) {
  if (y >= eps) return 1.0 / y;
  return 2.0 / eps - y / (eps * eps);
}

// Hessian of f0(|u|) in u, y = |u|: (f1 / y) I + (f1' - f1 / y) u u^T / y^2.
//   y >= eps: f1 = 1, f1' = 0:  (1 / y) I - u u^T / y^3       (eigenvalues 1 / y and 0)
//   y <  eps: f1' - f1 / y = (2 / eps - 2 y / eps^2) - (2 / eps - y / eps^2) = -y / eps^2,
//             so (f1 / y) I - u u^T / (eps^2 y)                (eigenvalues f1 / y and
//             2 (eps - y) / eps^2, both >= 0; the second term vanishes as y -> 0)
// PSD in both cases, as f0(|u|) is convex: IPC's projection (section 5) changes nothing here.
Eigen::Matrix2d friction_tangent_hessian(const Eigen::Vector2d& u, double eps) {
  const double y = u.norm();
  Eigen::Matrix2d h = friction_f1_over_y(y, eps) * Eigen::Matrix2d::Identity();
  if (y >= eps) {
    h -= (u * u.transpose()) / (y * y * y);
  } else if (y > 0.0) {
    h -= (u * u.transpose()) / (eps * eps * y);
  }
  return h;
}

std::array<double, 4> closest_point_weights(const ContactPair& pair, const std::array<Vec3, 4>& p) {
  switch (pair.kind) {
    case ContactKind::point_triangle: {
      const auto b = closest_on_triangle(p[0], p[1], p[2], p[3]);
      return {1.0, -b[0], -b[1], -b[2]};
    }
    case ContactKind::edge_edge: {
      const auto [s, t] = closest_on_edges(p[0], p[1], p[2], p[3]);
      return {1.0 - s, s, -(1.0 - t), -t};
    }
    case ContactKind::ground:
      return {1.0, 0.0, 0.0, 0.0};
  }
  return {};
}

std::optional<FrictionPair> lag_friction_pair(const ContactPair& pair, const std::array<Vec3, 4>& p,
                                              double ground, double kappa,
                                              const LogBarrier& barrier, double mu) {
  if (!(mu > 0.0)) return std::nullopt;
  const double d = contact_distance_squared(pair, p, ground);
  if (!(d > 0.0) || d >= barrier.dhat()) return std::nullopt;
  FrictionPair f;
  f.kind = pair.kind;
  f.vertices = pair.vertices;
  f.count = pair.vertex_count();
  f.weights = closest_point_weights(pair, p);
  Vec3 normal = Vec3::UnitY();  // the ground's
  if (pair.kind != ContactKind::ground) {
    Vec3 separation = Vec3::Zero();
    for (int i = 0; i < f.count; ++i) separation += f.weights[i] * p[i];
    const double length = separation.norm();
    if (!(length > 0.0)) return std::nullopt;  // no direction to slide across
    normal = separation / length;
  }
  f.basis = tangent_basis(normal);
  f.normal_force = kappa * -barrier.first_derivative(d) * 2.0 * std::sqrt(d);
  f.mu_lambda = mu * f.normal_force;
  return f;
}

Eigen::Vector2d friction_tangent_motion(const FrictionPair& pair, const Eigen::VectorXd& x,
                                        const Eigen::VectorXd& x_start, int cloth_vertices) {
  Vec3 r = pair.obstacle_motion;
  for (int i = 0; i < pair.count; ++i) {
    const int v = pair.vertices[i];
    if (v < cloth_vertices)
      r += pair.weights[i] * (x.segment<3>(3 * v) - x_start.segment<3>(3 * v));
  }
  return pair.basis.transpose() * r;
}

}  // namespace animkit
