#pragma once
// Unsigned squared distances between the primitives of a triangle mesh, with exact gradients and
// Hessians, the way Incremental Potential Contact evaluates them (Li et al., SIGGRAPH 2020,
// section 4 and its supplement): the distance between a point and a triangle, or between two
// edges, is not smooth across the Voronoi regions of the primitives' features, so a classifier
// (distance_type.h) first says which feature pair is closest and the caller then evaluates the
// smooth formula of that pair:
//   point-point   |p - q|^2                                      (6 dofs)
//   point-line    |e x u|^2 / |u|^2,          e = p - a, u = b - a          (9 dofs)
//   point-plane   (e . (u x v))^2 / |u x v|^2, e = p - a, u = b - a, v = c - a (12 dofs)
//   line-line     the same as point-plane with e = a0 - b0, u = a1 - a0, v = b1 - b0 (12 dofs)
// All are squared distances (the barrier takes squared distances, so no square root and no
// singularity at contact). Units: the squared unit of the positions (m^2 for positions in m).
//
// Derivatives are written in the reduced variables (e, u, v) and mapped to the vertices by the
// constant linear map z = J x (J has +-I blocks): grad_x = J^T grad_z, hess_x = J^T hess_z J.
// The derivation is above each formula in src/collision/distance.cpp.
#include <Eigen/Core>

#include "animkit/core/types.h"

namespace animkit {

/// A function of `Vertices` stacked 3D points, its gradient and its Hessian with respect to the
/// 3 * Vertices coordinates in vertex-major order (x0 y0 z0 x1 y1 z1 ...), in the order the
/// function takes its points.
template <int Vertices>
struct StencilDerivatives {
  static constexpr int kDofs = 3 * Vertices;  ///< number of coordinates: 3 per vertex
  double value = 0.0;                         ///< the function's value
  /// First derivatives with respect to the kDofs coordinates.
  Eigen::Matrix<double, kDofs, 1> gradient = Eigen::Matrix<double, kDofs, 1>::Zero();
  /// Second derivatives (symmetric kDofs x kDofs) with respect to the kDofs coordinates.
  Eigen::Matrix<double, kDofs, kDofs> hessian = Eigen::Matrix<double, kDofs, kDofs>::Zero();
};

/// A function of `Vertices` stacked 3D points and its gradient alone (as StencilDerivatives,
/// without the Hessian): for the barrier's gradient and its Gauss-Newton Hessian, which need no
/// second derivatives of the distance. The same numbers as the matching *_derivatives.
template <int Vertices>
struct StencilGradient {
  static constexpr int kDofs = 3 * Vertices;  ///< number of coordinates: 3 per vertex
  double value = 0.0;                         ///< the function's value
  /// First derivatives with respect to the kDofs coordinates.
  Eigen::Matrix<double, kDofs, 1> gradient = Eigen::Matrix<double, kDofs, 1>::Zero();
};

/// |p - q|^2.
double point_point_distance_squared(const Vec3& p, const Vec3& q);
/// |p - q|^2 and its derivatives in (p, q).
StencilDerivatives<2> point_point_distance_squared_derivatives(const Vec3& p, const Vec3& q);
/// Its value and gradient alone.
StencilGradient<2> point_point_distance_squared_gradient(const Vec3& p, const Vec3& q);

/// Squared distance from p to the infinite line through a and b. Requires a != b.
double point_line_distance_squared(const Vec3& p, const Vec3& a, const Vec3& b);
/// The same and its derivatives in (p, a, b). Requires a != b.
StencilDerivatives<3> point_line_distance_squared_derivatives(const Vec3& p, const Vec3& a,
                                                              const Vec3& b);
/// Its value and gradient alone.
StencilGradient<3> point_line_distance_squared_gradient(
    const Vec3& p, const Vec3& a, const Vec3& b);

/// Squared distance from p to the plane through a, b, c. Requires a non-degenerate triangle
/// ((b - a) x (c - a) != 0).
double point_plane_distance_squared(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);
/// The same and its derivatives in (p, a, b, c).
StencilDerivatives<4> point_plane_distance_squared_derivatives(const Vec3& p, const Vec3& a,
                                                               const Vec3& b, const Vec3& c);
/// Its value and gradient alone.
StencilGradient<4> point_plane_distance_squared_gradient(
    const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// Squared distance between the infinite line through a0, a1 and the one through b0, b1.
/// Requires non-parallel lines ((a1 - a0) x (b1 - b0) != 0).
double line_line_distance_squared(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1);
/// The same and its derivatives in (a0, a1, b0, b1).
StencilDerivatives<4> line_line_distance_squared_derivatives(const Vec3& a0, const Vec3& a1,
                                                             const Vec3& b0, const Vec3& b1);
/// Its value and gradient alone.
StencilGradient<4> line_line_distance_squared_gradient(
    const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1);

}  // namespace animkit
