#include "contact_pair.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <optional>

#include "animkit/collision/closest_points.h"
#include "animkit/collision/distance_type.h"
#include "animkit/collision/edge_edge_mollifier.h"
#include "animkit/collision/psd_projection.h"

namespace animkit {

namespace {

// A sphere pair's squared gap d = (s - r)^2 from the squared distance q = s^2 of its centre to
// the triangle, and d's first and second derivatives in q (contact_pair.h); d = 0 (contact)
// when the triangle reaches into the sphere.
struct SphereGap {
  double squared = 0.0, first = 0.0, second = 0.0;
};

SphereGap sphere_gap(double q, double radius) {
  const double s = std::sqrt(q);
  if (!(s > radius)) return {};
  return {(s - radius) * (s - radius), 1.0 - radius / s, radius / (2.0 * s * q)};
}

// The rows of an orthonormal basis of the directions a sphere's gap over the face of the triangle
// (p[1], p[2], p[3]) depends on to second order, or none for a degenerate triangle. That gap is
// the centre's height s over the triangle's plane. Moving the corners along the normal n (three
// directions) lifts and tilts the plane; moving them within it changes s only together with a
// tilt, through the point under the centre, sum_j beta_j u_j (beta its barycentric coordinates):
// a tilted plane slid under the centre rises or falls there. Nothing else moves s at first or
// second order, so the 9 x 9 block is B^T K B with K = B H B^T its 5 x 5 part.
std::optional<Eigen::Matrix<double, 5, 9>> face_gap_basis(const std::array<Vec3, 4>& p) {
  const Vec3 e1 = p[2] - p[1], e2 = p[3] - p[1];
  const Vec3 normal = e1.cross(e2);
  if (!(normal.squaredNorm() > 1e-12 * e1.squaredNorm() * e2.squaredNorm())) return std::nullopt;
  const std::array<double, 3> under = closest_on_triangle(p[0], p[1], p[2], p[3]);
  const Eigen::Vector3d beta = Eigen::Vector3d(under[0], under[1], under[2]).normalized();
  const Vec3 n = normal.normalized(), t1 = e1.normalized(), t2 = n.cross(t1);
  Eigen::Matrix<double, 5, 9> basis = Eigen::Matrix<double, 5, 9>::Zero();
  for (int v = 0; v < 3; ++v) {
    basis.block<1, 3>(v, 3 * v) = n.transpose();
    basis.block<1, 3>(3, 3 * v) = beta[v] * t1.transpose();
    basis.block<1, 3>(4, 3 * v) = beta[v] * t2.transpose();
  }
  return basis;
}

// A sphere's pair's Hessian onto the PSD cone where Newton sees it. The centre is no unknown (a
// collider follows its motion): only the cloth's block enters Newton's matrix, and that block
// alone needs to be PSD. With the triangle's nearest point on an edge, the third vertex has
// no part in the gap: the edge's 6 x 6 block is projected, at a third of the 9 x 9's cost.
// Over the face the block lives in five directions (face_gap_basis), whose 5 x 5 part is
// projected instead: the same matrix, since the basis is orthonormal.
void project_sphere_pair(const std::array<Vec3, 4>& p, Eigen::Matrix<double, 12, 12>& hessian) {
  std::array<int, 2> edge{-1, -1};  // slots of the edge's vertices
  const PointTriangleDistanceType type = point_triangle_distance_type(p[0], p[1], p[2], p[3]);
  switch (type) {
    case PointTriangleDistanceType::kEdgeAB:
      edge = {1, 2};
      break;
    case PointTriangleDistanceType::kEdgeBC:
      edge = {2, 3};
      break;
    case PointTriangleDistanceType::kEdgeCA:
      edge = {3, 1};
      break;
    default:
      break;
  }
  if (edge[0] < 0) {
    const Eigen::Matrix<double, 9, 9> cloth = hessian.bottomRightCorner<9, 9>();
    hessian.setZero();
    const auto basis =
        type == PointTriangleDistanceType::kInterior ? face_gap_basis(p) : std::nullopt;
    if (basis) {
      const Eigen::Matrix<double, 5, 5> part = *basis * cloth * basis->transpose();
      hessian.bottomRightCorner<9, 9>() = basis->transpose() * project_to_psd(part) * *basis;
    } else {
      hessian.bottomRightCorner<9, 9>() = project_to_psd(cloth);
    }
    return;
  }
  Eigen::Matrix<double, 6, 6> block;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      block.block<3, 3>(3 * i, 3 * j) = hessian.block<3, 3>(3 * edge[i], 3 * edge[j]);
  block = project_to_psd(block);
  hessian.setZero();
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      hessian.block<3, 3>(3 * edge[i], 3 * edge[j]) = block.block<3, 3>(3 * i, 3 * j);
}

StencilDerivatives<4> distance_derivatives(const ContactPair& pair, const std::array<Vec3, 4>& p,
                                           double ground) {
  switch (pair.kind) {
    case ContactKind::point_triangle: {
      StencilDerivatives<4> d = point_triangle_distance_squared_derivatives(
          p[0], p[1], p[2], p[3], point_triangle_distance_type(p[0], p[1], p[2], p[3]));
      if (pair.thickness > 0.0) {
        const SphereGap gap = sphere_gap(d.value, pair.thickness);
        d.hessian = gap.first * d.hessian + gap.second * d.gradient * d.gradient.transpose();
        d.gradient *= gap.first;
        d.value = gap.squared;
      }
      return d;
    }
    case ContactKind::edge_edge:
      return edge_edge_distance_squared_derivatives(
          p[0], p[1], p[2], p[3], edge_edge_distance_type(p[0], p[1], p[2], p[3]));
    case ContactKind::ground: {
      // d = (y - height)^2: only the particle's y enters.
      StencilDerivatives<4> d;
      const double gap = p[0].y() - ground;
      d.value = gap * gap;
      d.gradient[1] = 2.0 * gap;
      d.hessian(1, 1) = 2.0;
      return d;
    }
  }
  assert(false && "unknown contact kind");
  return {};
}

// The same value and gradient without the Hessian: for the barrier's gradient and its
// Gauss-Newton Hessian, which need none (the distance's Hessian is most of the cost).
StencilGradient<4> distance_gradient(const ContactPair& pair, const std::array<Vec3, 4>& p,
                                     double ground) {
  switch (pair.kind) {
    case ContactKind::point_triangle: {
      StencilGradient<4> d = point_triangle_distance_squared_gradient(
          p[0], p[1], p[2], p[3], point_triangle_distance_type(p[0], p[1], p[2], p[3]));
      if (pair.thickness > 0.0) {
        const SphereGap gap = sphere_gap(d.value, pair.thickness);
        d.gradient *= gap.first;
        d.value = gap.squared;
      }
      return d;
    }
    case ContactKind::edge_edge:
      return edge_edge_distance_squared_gradient(
          p[0], p[1], p[2], p[3], edge_edge_distance_type(p[0], p[1], p[2], p[3]));
    case ContactKind::ground: {
      StencilGradient<4> d;
      const double gap = p[0].y() - ground;
      d.value = gap * gap;
      d.gradient[1] = 2.0 * gap;
      return d;
    }
  }
  assert(false && "unknown contact kind");
  return {};
}

}  // namespace

double contact_distance_squared(const ContactPair& pair, const std::array<Vec3, 4>& p,
                                double ground) {
  switch (pair.kind) {
    case ContactKind::point_triangle: {
      const double q = point_triangle_distance_squared(p[0], p[1], p[2], p[3]);
      return pair.thickness > 0.0 ? sphere_gap(q, pair.thickness).squared : q;
    }
    case ContactKind::edge_edge:
      return edge_edge_distance_squared(p[0], p[1], p[2], p[3]);
    case ContactKind::ground: {
      const double gap = p[0].y() - ground;
      // Below the plane counts as contact (0), not as the mirrored distance above it.
      return gap > 0.0 ? gap * gap : 0.0;
    }
  }
  assert(false && "unknown contact kind");
  return 0.0;
}

double contact_barrier(const ContactPair& pair, const std::array<Vec3, 4>& p, double ground,
                       const LogBarrier& barrier) {
  if (contact_beyond(pair, p, barrier.dhat())) return 0.0;
  const double d = contact_distance_squared(pair, p, ground);
  if (!(d > 0.0)) return std::numeric_limits<double>::infinity();
  if (d >= barrier.dhat()) return 0.0;
  const double b = barrier.value(d);
  if (pair.kind != ContactKind::edge_edge) return b;
  return b * edge_edge_mollifier(p[0], p[1], p[2], p[3], pair.mollifier_threshold);
}

StencilDerivatives<4> contact_barrier_derivatives(const ContactPair& pair,
                                                  const std::array<Vec3, 4>& p, double ground,
                                                  const LogBarrier& barrier, bool project) {
  StencilDerivatives<4> out;
  const StencilDerivatives<4> d = distance_derivatives(pair, p, ground);
  assert(d.value > 0.0 && "a contact pair's derivatives need a positive distance");
  if (!(d.value < barrier.dhat())) return out;  // inactive: all zero
  const double b = barrier.value(d.value);
  const double b1 = barrier.first_derivative(d.value);
  const double b2 = barrier.second_derivative(d.value);
  out.value = b;
  out.gradient = b1 * d.gradient;
  out.hessian = b2 * d.gradient * d.gradient.transpose() + b1 * d.hessian;
  if (pair.kind == ContactKind::ground) {
    // One coordinate: projecting onto the PSD cone is clamping it.
    if (project) out.hessian(1, 1) = std::max(out.hessian(1, 1), 0.0);
    return out;
  }
  if (pair.kind == ContactKind::edge_edge) {
    const StencilDerivatives<4> m =
        edge_edge_mollifier_derivatives(p[0], p[1], p[2], p[3], pair.mollifier_threshold);
    out.hessian = m.value * out.hessian +
                  b1 * (m.gradient * d.gradient.transpose() + d.gradient * m.gradient.transpose()) +
                  b * m.hessian;
    out.gradient = m.value * out.gradient + b * m.gradient;
    out.value = m.value * b;
  }
  if (!project) return out;
  if (pair.thickness > 0.0) {
    project_sphere_pair(p, out.hessian);
    return out;
  }
  out.hessian = project_to_psd(out.hessian);
  return out;
}

Eigen::Matrix<double, 12, 12> contact_barrier_gauss_newton_hessian(const ContactPair& pair,
                                                                   const std::array<Vec3, 4>& p,
                                                                   double ground,
                                                                   const LogBarrier& barrier) {
  const StencilGradient<4> d = distance_gradient(pair, p, ground);
  assert(d.value > 0.0 && "a contact pair's derivatives need a positive distance");
  if (!(d.value < barrier.dhat())) return Eigen::Matrix<double, 12, 12>::Zero();  // inactive
  const double curvature = std::max(
      2.0 * barrier.first_derivative(d.value) + 4.0 * d.value * barrier.second_derivative(d.value),
      0.0);
  double weight = curvature / (4.0 * d.value);
  if (pair.kind == ContactKind::edge_edge)
    weight *= edge_edge_mollifier(p[0], p[1], p[2], p[3], pair.mollifier_threshold);
  return weight * d.gradient * d.gradient.transpose();
}

bool gauss_newton_suffices(const ContactPair& pair, const std::array<Vec3, 4>& p) {
  if (pair.thickness == 0.0) return true;
  switch (point_triangle_distance_type(p[0], p[1], p[2], p[3])) {
    case PointTriangleDistanceType::kPointA:
    case PointTriangleDistanceType::kPointB:
    case PointTriangleDistanceType::kPointC:
      return true;
    default:
      return false;
  }
}

Eigen::Matrix<double, 12, 1> contact_barrier_gradient(const ContactPair& pair,
                                                      const std::array<Vec3, 4>& p, double ground,
                                                      const LogBarrier& barrier) {
  const StencilGradient<4> d = distance_gradient(pair, p, ground);
  assert(d.value > 0.0 && "a contact pair's derivatives need a positive distance");
  if (!(d.value < barrier.dhat())) return Eigen::Matrix<double, 12, 1>::Zero();  // inactive
  Eigen::Matrix<double, 12, 1> gradient = barrier.first_derivative(d.value) * d.gradient;
  if (pair.kind == ContactKind::edge_edge) {
    const StencilGradient<4> m =
        edge_edge_mollifier_gradient(p[0], p[1], p[2], p[3], pair.mollifier_threshold);
    gradient = m.value * gradient + barrier.value(d.value) * m.gradient;
  }
  return gradient;
}

}  // namespace animkit
