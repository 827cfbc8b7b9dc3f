#include "friction_pair.h"

#include <algorithm>
#include <cmath>

#include "animkit/collision/distance_type.h"

namespace animkit {

namespace {

// num / den clamped to [0, 1]; 0 for a degenerate denominator (a zero-length edge).
double clamped_ratio(double num, double den) {
  return den > 0.0 ? std::clamp(num / den, 0.0, 1.0) : 0.0;
}

// Barycentric coordinates of the point of triangle (a, b, c) closest to p: Ericson 2005,
// section 5.1.5, the Voronoi regions of the vertices, then the edges, then the face. A
// degenerate (zero-area) triangle that reaches the face case takes its nearest edge instead.
std::array<double, 3> closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                          const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {1.0, 0.0, 0.0};
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {0.0, 1.0, 0.0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = clamped_ratio(d1, d1 - d3);
    return {1.0 - v, v, 0.0};
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {0.0, 0.0, 1.0};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = clamped_ratio(d2, d2 - d6);
    return {1.0 - w, 0.0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    const double w = clamped_ratio(d4 - d3, (d4 - d3) + (d5 - d6));
    return {0.0, 1.0 - w, w};
  }
  const double sum = va + vb + vc;
  if (sum > kParallelTolerance * ab.squaredNorm() * ac.squaredNorm()) {
    const double v = vb / sum, w = vc / sum;
    return {1.0 - v - w, v, w};
  }
  // Zero area: the nearest of the three edges.
  const auto on_edge = [&](const Vec3& s, const Vec3& e) {
    return clamped_ratio((p - s).dot(e - s), (e - s).squaredNorm());
  };
  const double tab = on_edge(a, b), tbc = on_edge(b, c), tca = on_edge(c, a);
  const double dab = (p - (a + tab * ab)).squaredNorm();
  const double dbc = (p - (b + tbc * (c - b))).squaredNorm();
  const double dca = (p - (c + tca * (a - c))).squaredNorm();
  if (dab <= dbc && dab <= dca) return {1.0 - tab, tab, 0.0};
  if (dbc <= dca) return {0.0, 1.0 - tbc, tbc};
  return {tca, 0.0, 1.0 - tca};
}

// Parameters (s, t) of the closest points a0 + s (a1 - a0), b0 + t (b1 - b0): Ericson 2005,
// section 5.1.9 (clamped to the segments; parallel edges take s = 0, at the same distance).
std::array<double, 2> closest_on_edges(const Vec3& a0, const Vec3& a1, const Vec3& b0,
                                       const Vec3& b1) {
  const Vec3 u = a1 - a0, v = b1 - b0, r = a0 - b0;
  const double a = u.squaredNorm(), e = v.squaredNorm(), f = v.dot(r);
  if (!(a > 0.0) && !(e > 0.0)) return {0.0, 0.0};
  if (!(a > 0.0)) return {0.0, clamped_ratio(f, e)};
  const double c = u.dot(r);
  if (!(e > 0.0)) return {clamped_ratio(-c, a), 0.0};
  const double b = u.dot(v), denom = a * e - b * b;
  double s =
      denom > kParallelTolerance * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0.0) {
    t = 0.0;
    s = clamped_ratio(-c, a);
  } else if (t > 1.0) {
    t = 1.0;
    s = clamped_ratio(b - c, a);
  }
  return {s, t};
}

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
