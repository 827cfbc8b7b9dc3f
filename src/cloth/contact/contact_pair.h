#pragma once
// One contact pair's barrier, kappa b(d(x)) (IPC, Li et al. 2020, eq. 6 and section 4): its
// value, gradient and PSD-projected Hessian in the pair's (up to) four vertices.
//   point-triangle  d = the classified point-triangle squared distance (distance_type.h)
//   edge-edge       d = the classified edge-edge squared distance, times IPC's mollifier m
//                   (edge_edge_mollifier.h), which fades the pair out as the edges turn
//                   parallel, where d is not smooth: the energy is m(x) b(d(x))
//   ground          d = (y - height)^2 for one particle above the plane y = height
//   sphere          a point-triangle pair whose point is a sphere collider's centre, r its
//                   radius: d = (s - r)^2 with s^2 = q the classified point-triangle squared
//                   distance, the squared gap between the triangle and the sphere's exact
//                   surface (C-IPC's thickness, Li et al. 2021, section 4). With D' = 1 - r / s
//                   and D'' = r / (2 s^3) its derivatives in q: grad d = D' grad q and
//                   hess d = D' hess q + D'' grad q grad q^T. Everything below takes d as is.
// Chain rule: grad (m b) = m b' grad d + b grad m; hess = m (b'' grad d grad d^T + b' hess d)
// + b' (grad m grad d^T + grad d grad m^T) + b hess m; then projected onto the PSD cone (as
// IPC does for every pair) so Newton's direction is a descent direction.
#include <array>
#include <cstdint>

#include "animkit/collision/barrier.h"
#include "animkit/collision/distance.h"
#include "animkit/core/types.h"

namespace animkit {

enum class ContactKind : std::uint8_t { point_triangle, edge_edge, ground };

/// Vertices in the contact's index space: the cloth's particles [0, N), then the obstacles'
/// vertices. point_triangle: (p, a, b, c); edge_edge: (a0, a1, b0, b1); ground: (p, -1, -1, -1).
struct ContactPair {
  ContactKind kind = ContactKind::point_triangle;
  std::array<int, 4> vertices{-1, -1, -1, -1};
  double mollifier_threshold = 0.0;  ///< edge_edge: eps_x (length^4), from rest lengths
  /// point_triangle whose point is a sphere's centre: the sphere's radius (m), by which the
  /// pair's distance falls short of the point's; 0 for every other pair.
  double thickness = 0.0;

  int vertex_count() const { return kind == ContactKind::ground ? 1 : 4; }
  bool operator==(const ContactPair&) const = default;
};

/// How far apart the axis-aligned boxes around the pair's two primitives are, along the axis
/// that separates them most (<= 0 when the boxes overlap), each box holding its primitive at
/// both positions `a` and `b` (the two ends of a linear move; pass one configuration twice),
/// less the pair's thickness. The pair's distance is at least that anywhere on the move. Not
/// for ground pairs.
inline double contact_box_gap(const ContactPair& pair, const std::array<Vec3, 4>& a,
                              const std::array<Vec3, 4>& b) {
  const int first = pair.kind == ContactKind::point_triangle ? 1 : 2;
  Vec3 lo[2] = {a[0].cwiseMin(b[0]), a[first].cwiseMin(b[first])};
  Vec3 hi[2] = {a[0].cwiseMax(b[0]), a[first].cwiseMax(b[first])};
  for (int i = 1; i < 4; ++i) {
    const int side = i < first ? 0 : 1;
    lo[side] = lo[side].cwiseMin(a[i]).cwiseMin(b[i]);
    hi[side] = hi[side].cwiseMax(a[i]).cwiseMax(b[i]);
  }
  return (lo[1] - hi[0]).cwiseMax(lo[0] - hi[1]).maxCoeff() - pair.thickness;
}

/// True when the pair's two primitives are certainly farther apart than sqrt(dhat): their
/// axis-aligned boxes lie more than that apart along some axis. A few comparisons against the
/// dozens of operations of a classified distance; most candidate pairs are beyond dhat (about
/// four in five while a sheet rests on a ball), so the loops over pairs test this first.
/// With a relative margin of 1e-6, a pair it passes over has a computed squared distance of
/// at least dhat as well: skipping it changes no result. Never true for ground pairs.
inline bool contact_beyond(const ContactPair& pair, const std::array<Vec3, 4>& p, double dhat) {
  if (pair.kind == ContactKind::ground) return false;
  const double gap = contact_box_gap(pair, p, p);
  return gap > 0.0 && gap * gap > (1.0 + 1e-6) * dhat;
}

/// The pair's squared distance at positions p (p[i] the position of vertices[i]); `ground`
/// is the plane's height. For edge-edge pairs this is the unmollified distance; for a sphere's
/// pairs the squared gap to its surface, 0 when the triangle reaches into the sphere.
double contact_distance_squared(const ContactPair& pair, const std::array<Vec3, 4>& p,
                                double ground);

/// b(d) times the mollifier (edge-edge), without kappa; +infinity at or past contact (d <= 0),
/// 0 at or beyond dhat.
double contact_barrier(const ContactPair& pair, const std::array<Vec3, 4>& p, double ground,
                       const LogBarrier& barrier);

/// The barrier (as contact_barrier) with its gradient and Hessian in the pair's vertices (rows
/// of unused vertices zero), the Hessian projected onto the PSD cone unless `project` is
/// false (for tests against finite differences). The pair must be at a positive distance.
StencilDerivatives<4> contact_barrier_derivatives(const ContactPair& pair,
                                                  const std::array<Vec3, 4>& p, double ground,
                                                  const LogBarrier& barrier, bool project = true);

/// A Gauss-Newton Hessian of the barrier, PSD by construction (no eigendecomposition): with
/// s = sqrt(d) the unsquared distance and B(s) = b(s^2), the pair's energy m B(s(x)) has the
/// Hessian m B''(s) grad s grad s^T plus terms in the curvature of s and of the mollifier m;
/// keeping the first alone, with B''(s) = 2 b'(d) + 4 d b''(d) clamped at 0, gives the
/// rank-one m max(B'', 0) grad d grad d^T / (4 d) (grad s = grad d / (2 s)). This is how
/// Offset Geometric Contact treats its pairs (Chen et al. 2025, section 3.6). The pair must be
/// at a positive distance; zero beyond dhat.
Eigen::Matrix<double, 12, 12> contact_barrier_gauss_newton_hessian(const ContactPair& pair,
                                                                   const std::array<Vec3, 4>& p,
                                                                   double ground,
                                                                   const LogBarrier& barrier);

/// Whether the Gauss-Newton Hessian does for the pair: not for a sphere's pair whose closest
/// point is on an edge or inside the triangle. Turning the triangle about that point brings it
/// closer to the sphere (its distance goes as r cos(angle)), a curvature of the gap that only
/// the exact Hessian holds; Gauss-Newton's steps turn it into the sphere, and CCD cuts them
/// short (a 5 x 5 sheet on a ball at 100 m/s: 192 Newton iterations a step instead of 37). At a
/// triangle's vertex the gap is the vertex's distance to the sphere, whose only curvature is
/// across the normal, where the projection clamps it: there both Hessians are the same.
bool gauss_newton_suffices(const ContactPair& pair, const std::array<Vec3, 4>& p);

/// The barrier's gradient alone (the same numbers as contact_barrier_derivatives' gradient),
/// without the Hessian's assembly and projection, which cost most of a pair's evaluation.
Eigen::Matrix<double, 12, 1> contact_barrier_gradient(const ContactPair& pair,
                                                      const std::array<Vec3, 4>& p, double ground,
                                                      const LogBarrier& barrier);

}  // namespace animkit
