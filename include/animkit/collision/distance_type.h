#pragma once
// Which features of two primitives are closest, and the distance of the pair through the smooth
// formula of those features (IPC, Li et al. 2020, section 4 and supplement: the unsigned
// distance is a piecewise combination of point-point, point-line, point-plane and line-line
// distances, each smooth in its own region).
//
// Point-segment: closest to an end point, or to the segment's interior (point-line).
// Point-triangle: the Voronoi regions of the triangle (Ericson, Real-Time Collision Detection,
//   2005, section 5.1.5): a vertex (point-point), an edge (point-line) or the face (point-plane).
// Edge-edge: the closest points' parameters (s on edge a, t on edge b) each at 0, at 1 or
//   inside (Ericson section 5.1.9) give 9 cases: 4 end-point pairs (point-point), 4 end points
//   against the other edge (point-line) and both inside (line-line). Parallel edges, where the
//   line-line formula divides by |u x v|^2 ~ 0, fall back to an end point against the other edge,
//   which is at the same distance when the edges are exactly parallel.
// A degenerate primitive (zero-length edge, zero-area triangle) is classified to its boundary
// features, never to a formula that would divide by zero.
#include "animkit/collision/distance.h"
#include "animkit/core/types.h"

namespace animkit {

enum class PointEdgeDistanceType { kPointA, kPointB, kInterior };

enum class PointTriangleDistanceType {
  kPointA,
  kPointB,
  kPointC,
  kEdgeAB,
  kEdgeBC,
  kEdgeCA,
  kInterior,
};

/// Edge a = (a0, a1), edge b = (b0, b1). kA0B1: a0 against b1 (point-point); kA0EdgeB: a0
/// against the line of edge b; kB1EdgeA: b1 against the line of edge a; kInterior: line-line.
enum class EdgeEdgeDistanceType {
  kA0B0,
  kA0B1,
  kA1B0,
  kA1B1,
  kA0EdgeB,
  kA1EdgeB,
  kB0EdgeA,
  kB1EdgeA,
  kInterior,
};

/// |u x v|^2 <= kParallelTolerance |u|^2 |v|^2 (sine of the angle below 1e-10) counts as
/// parallel edges or a degenerate triangle: the formulas dividing by |u x v|^2 are not used.
inline constexpr double kParallelTolerance = 1e-20;

/// Closest feature of segment (a, b) to point p.
PointEdgeDistanceType point_edge_distance_type(const Vec3& p, const Vec3& a, const Vec3& b);
/// Closest feature of triangle (a, b, c) to point p.
PointTriangleDistanceType point_triangle_distance_type(const Vec3& p, const Vec3& a, const Vec3& b,
                                                       const Vec3& c);
/// Closest feature pair of segments (a0, a1) and (b0, b1).
EdgeEdgeDistanceType edge_edge_distance_type(const Vec3& a0, const Vec3& a1, const Vec3& b0,
                                             const Vec3& b1);

/// Squared distance from p to segment (a, b) by the formula of `type` (squared position units).
/// The type must come from point_edge_distance_type (or name a feature the formula allows).
double point_edge_distance_squared(const Vec3& p, const Vec3& a, const Vec3& b,
                                   PointEdgeDistanceType type);
/// Derivatives in (p, a, b) of the formula of `type` (zero rows for unused vertices).
StencilDerivatives<3> point_edge_distance_squared_derivatives(const Vec3& p, const Vec3& a,
                                                              const Vec3& b,
                                                              PointEdgeDistanceType type);

/// Squared distance from p to triangle (a, b, c) by the formula of `type`.
double point_triangle_distance_squared(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                                       PointTriangleDistanceType type);
/// Derivatives in (p, a, b, c) of the formula of `type`.
StencilDerivatives<4> point_triangle_distance_squared_derivatives(const Vec3& p, const Vec3& a,
                                                                  const Vec3& b, const Vec3& c,
                                                                  PointTriangleDistanceType type);
/// Its value and gradient alone (the same numbers).
StencilGradient<4> point_triangle_distance_squared_gradient(const Vec3& p, const Vec3& a,
                                                            const Vec3& b, const Vec3& c,
                                                            PointTriangleDistanceType type);

/// Squared distance between segments (a0, a1) and (b0, b1) by the formula of `type`.
double edge_edge_distance_squared(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1,
                                  EdgeEdgeDistanceType type);
/// Derivatives in (a0, a1, b0, b1) of the formula of `type`.
StencilDerivatives<4> edge_edge_distance_squared_derivatives(const Vec3& a0, const Vec3& a1,
                                                             const Vec3& b0, const Vec3& b1,
                                                             EdgeEdgeDistanceType type);
/// Its value and gradient alone (the same numbers).
StencilGradient<4> edge_edge_distance_squared_gradient(const Vec3& a0, const Vec3& a1,
                                                       const Vec3& b0, const Vec3& b1,
                                                       EdgeEdgeDistanceType type);

/// The unsigned squared distances, classified: the minimum over the primitives' points.
inline double point_edge_distance_squared(const Vec3& p, const Vec3& a, const Vec3& b) {
  return point_edge_distance_squared(p, a, b, point_edge_distance_type(p, a, b));
}
inline double point_triangle_distance_squared(const Vec3& p, const Vec3& a, const Vec3& b,
                                              const Vec3& c) {
  return point_triangle_distance_squared(p, a, b, c, point_triangle_distance_type(p, a, b, c));
}
inline double edge_edge_distance_squared(const Vec3& a0, const Vec3& a1, const Vec3& b0,
                                         const Vec3& b1) {
  return edge_edge_distance_squared(a0, a1, b0, b1, edge_edge_distance_type(a0, a1, b0, b1));
}

}  // namespace animkit
