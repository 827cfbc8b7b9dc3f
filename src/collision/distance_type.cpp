#include "animkit/collision/distance_type.h"

#include <algorithm>
#include <array>
#include <cassert>

namespace animkit {

namespace {

// Places the derivatives of a formula over some of a stencil's vertices into the whole
// stencil's: sub vertex i is stencil vertex index[i]; the other rows and columns stay zero.
// Stencil is StencilDerivatives or StencilGradient (no Hessian to place).
template <int Full, template <int> class Stencil, int Sub>
Stencil<Full> scatter(const Stencil<Sub>& sub, const std::array<int, Sub>& index) {
  Stencil<Full> out;
  out.value = sub.value;
  for (int i = 0; i < Sub; ++i) {
    out.gradient.template segment<3>(3 * index[i]) = sub.gradient.template segment<3>(3 * i);
    if constexpr (requires { sub.hessian; }) {
      for (int j = 0; j < Sub; ++j) {
        out.hessian.template block<3, 3>(3 * index[i], 3 * index[j]) =
            sub.hessian.template block<3, 3>(3 * i, 3 * j);
      }
    }
  }
  return out;
}

// The smooth formulas with their whole derivatives, or with their gradients alone.
struct WithHessian {
  template <int V>
  using Stencil = StencilDerivatives<V>;
  static Stencil<2> point_point(const Vec3& p, const Vec3& q) {
    return point_point_distance_squared_derivatives(p, q);
  }
  static Stencil<3> point_line(const Vec3& p, const Vec3& a, const Vec3& b) {
    return point_line_distance_squared_derivatives(p, a, b);
  }
  static Stencil<4> point_plane(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    return point_plane_distance_squared_derivatives(p, a, b, c);
  }
  static Stencil<4> line_line(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
    return line_line_distance_squared_derivatives(a0, a1, b0, b1);
  }
};
struct GradientOnly {
  template <int V>
  using Stencil = StencilGradient<V>;
  static Stencil<2> point_point(const Vec3& p, const Vec3& q) {
    return point_point_distance_squared_gradient(p, q);
  }
  static Stencil<3> point_line(const Vec3& p, const Vec3& a, const Vec3& b) {
    return point_line_distance_squared_gradient(p, a, b);
  }
  static Stencil<4> point_plane(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    return point_plane_distance_squared_gradient(p, a, b, c);
  }
  static Stencil<4> line_line(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
    return line_line_distance_squared_gradient(a0, a1, b0, b1);
  }
};

template <class F>
typename F::template Stencil<4> point_triangle_formula(const Vec3& p, const Vec3& a,
                                                        const Vec3& b, const Vec3& c,
                                                        PointTriangleDistanceType type) {
  using T = PointTriangleDistanceType;
  switch (type) {
    case T::kPointA:
      return scatter<4>(F::point_point(p, a), {0, 1});
    case T::kPointB:
      return scatter<4>(F::point_point(p, b), {0, 2});
    case T::kPointC:
      return scatter<4>(F::point_point(p, c), {0, 3});
    case T::kEdgeAB:
      return scatter<4>(F::point_line(p, a, b), {0, 1, 2});
    case T::kEdgeBC:
      return scatter<4>(F::point_line(p, b, c), {0, 2, 3});
    case T::kEdgeCA:
      return scatter<4>(F::point_line(p, c, a), {0, 3, 1});
    case T::kInterior:
      return F::point_plane(p, a, b, c);
  }
  assert(false && "unknown point-triangle distance type");
  return {};
}

template <class F>
typename F::template Stencil<4> edge_edge_formula(const Vec3& a0, const Vec3& a1, const Vec3& b0,
                                                   const Vec3& b1, EdgeEdgeDistanceType type) {
  using T = EdgeEdgeDistanceType;
  switch (type) {
    case T::kA0B0:
      return scatter<4>(F::point_point(a0, b0), {0, 2});
    case T::kA0B1:
      return scatter<4>(F::point_point(a0, b1), {0, 3});
    case T::kA1B0:
      return scatter<4>(F::point_point(a1, b0), {1, 2});
    case T::kA1B1:
      return scatter<4>(F::point_point(a1, b1), {1, 3});
    case T::kA0EdgeB:
      return scatter<4>(F::point_line(a0, b0, b1), {0, 2, 3});
    case T::kA1EdgeB:
      return scatter<4>(F::point_line(a1, b0, b1), {1, 2, 3});
    case T::kB0EdgeA:
      return scatter<4>(F::point_line(b0, a0, a1), {2, 0, 1});
    case T::kB1EdgeA:
      return scatter<4>(F::point_line(b1, a0, a1), {3, 0, 1});
    case T::kInterior:
      return F::line_line(a0, a1, b0, b1);
  }
  assert(false && "unknown edge-edge distance type");
  return {};
}

double clamp01(double x) {
  return std::clamp(x, 0.0, 1.0);
}

// 0, 1, or 2 for inside (0, 1).
int side(double parameter) {
  return parameter <= 0.0 ? 0 : (parameter >= 1.0 ? 1 : 2);
}

}  // namespace

PointEdgeDistanceType point_edge_distance_type(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 u = b - a;
  const double length2 = u.squaredNorm();
  const double t = (p - a).dot(u);  // the projection's parameter times |u|^2
  if (length2 == 0.0 || t <= 0.0) return PointEdgeDistanceType::kPointA;
  if (t >= length2) return PointEdgeDistanceType::kPointB;
  return PointEdgeDistanceType::kInterior;
}

PointTriangleDistanceType point_triangle_distance_type(const Vec3& p, const Vec3& a, const Vec3& b,
                                                       const Vec3& c) {
  using T = PointTriangleDistanceType;
  const Vec3 ab = b - a, ac = c - a;
  if (ab.cross(ac).squaredNorm() <= kParallelTolerance * ab.squaredNorm() * ac.squaredNorm()) {
    // Degenerate triangle: the nearest of its three edges (no face region to speak of).
    const std::array<std::array<T, 3>, 3> names = {{{T::kPointA, T::kPointB, T::kEdgeAB},
                                                    {T::kPointB, T::kPointC, T::kEdgeBC},
                                                    {T::kPointC, T::kPointA, T::kEdgeCA}}};
    const std::array<std::array<const Vec3*, 2>, 3> edges = {{{&a, &b}, {&b, &c}, {&c, &a}}};
    T best = T::kPointA;
    double best_distance = 0.0;
    for (int i = 0; i < 3; ++i) {
      const PointEdgeDistanceType type = point_edge_distance_type(p, *edges[i][0], *edges[i][1]);
      const double d = point_edge_distance_squared(p, *edges[i][0], *edges[i][1], type);
      if (i == 0 || d < best_distance) {
        best_distance = d;
        best = names[i][static_cast<int>(type)];
      }
    }
    return best;
  }
  // Ericson 2005, ClosestPtPointTriangle: the d's are the projections of p's offsets from the
  // vertices on the edges, the v's the unnormalized barycentric coordinates of the projection.
  const Vec3 ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return T::kPointA;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return T::kPointB;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return T::kEdgeAB;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return T::kPointC;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return T::kEdgeCA;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return T::kEdgeBC;
  return T::kInterior;
}

// Closest points a0 + s u and b0 + t v minimize |e + s u - t v|^2 (e = a0 - b0) over the unit
// square. Unconstrained, s = (B E - C D) / (A C - B^2) with A = u.u, B = u.v, C = v.v,
// D = u.e, E = v.e; Ericson's procedure clamps s, takes the best t for it, and if t had to be
// clamped takes the best s for that t; the result is the constrained minimum of this convex
// quadratic. Parallel edges start from s = 0 (any s of an overlap is as close).
EdgeEdgeDistanceType edge_edge_distance_type(const Vec3& a0, const Vec3& a1, const Vec3& b0,
                                             const Vec3& b1) {
  using T = EdgeEdgeDistanceType;
  const Vec3 u = a1 - a0, v = b1 - b0, e = a0 - b0;
  const double A = u.squaredNorm(), B = u.dot(v), C = v.squaredNorm();
  const double D = u.dot(e), E = v.dot(e);
  double s = 0.0, t = 0.0;
  if (A == 0.0 && C == 0.0) {
    return T::kA0B0;
  } else if (A == 0.0) {
    t = clamp01(E / C);
  } else if (C == 0.0) {
    s = clamp01(-D / A);
  } else {
    const double cross2 = u.cross(v).squaredNorm();  // = A C - B^2, without the cancellation
    s = cross2 <= kParallelTolerance * A * C ? 0.0 : clamp01((B * E - C * D) / cross2);
    t = (B * s + E) / C;
    if (t < 0.0) {
      t = 0.0;
      s = clamp01(-D / A);
    } else if (t > 1.0) {
      t = 1.0;
      s = clamp01((B - D) / A);
    }
  }
  // Rows: side of s (0, 1, inside); columns: side of t.
  static constexpr std::array<std::array<T, 3>, 3> kTable = {{
      {T::kA0B0, T::kA0B1, T::kA0EdgeB},
      {T::kA1B0, T::kA1B1, T::kA1EdgeB},
      {T::kB0EdgeA, T::kB1EdgeA, T::kInterior},
  }};
  return kTable[side(s)][side(t)];
}

double point_edge_distance_squared(const Vec3& p, const Vec3& a, const Vec3& b,
                                   PointEdgeDistanceType type) {
  switch (type) {
    case PointEdgeDistanceType::kPointA:
      return point_point_distance_squared(p, a);
    case PointEdgeDistanceType::kPointB:
      return point_point_distance_squared(p, b);
    case PointEdgeDistanceType::kInterior:
      return point_line_distance_squared(p, a, b);
  }
  assert(false && "unknown point-edge distance type");
  return 0.0;
}

StencilDerivatives<3> point_edge_distance_squared_derivatives(const Vec3& p, const Vec3& a,
                                                              const Vec3& b,
                                                              PointEdgeDistanceType type) {
  switch (type) {
    case PointEdgeDistanceType::kPointA:
      return scatter<3>(point_point_distance_squared_derivatives(p, a), {0, 1});
    case PointEdgeDistanceType::kPointB:
      return scatter<3>(point_point_distance_squared_derivatives(p, b), {0, 2});
    case PointEdgeDistanceType::kInterior:
      return point_line_distance_squared_derivatives(p, a, b);
  }
  assert(false && "unknown point-edge distance type");
  return {};
}

double point_triangle_distance_squared(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                                       PointTriangleDistanceType type) {
  using T = PointTriangleDistanceType;
  switch (type) {
    case T::kPointA:
      return point_point_distance_squared(p, a);
    case T::kPointB:
      return point_point_distance_squared(p, b);
    case T::kPointC:
      return point_point_distance_squared(p, c);
    case T::kEdgeAB:
      return point_line_distance_squared(p, a, b);
    case T::kEdgeBC:
      return point_line_distance_squared(p, b, c);
    case T::kEdgeCA:
      return point_line_distance_squared(p, c, a);
    case T::kInterior:
      return point_plane_distance_squared(p, a, b, c);
  }
  assert(false && "unknown point-triangle distance type");
  return 0.0;
}

StencilDerivatives<4> point_triangle_distance_squared_derivatives(const Vec3& p, const Vec3& a,
                                                                  const Vec3& b, const Vec3& c,
                                                                  PointTriangleDistanceType type) {
  return point_triangle_formula<WithHessian>(p, a, b, c, type);
}

StencilGradient<4> point_triangle_distance_squared_gradient(const Vec3& p, const Vec3& a,
                                                            const Vec3& b, const Vec3& c,
                                                            PointTriangleDistanceType type) {
  return point_triangle_formula<GradientOnly>(p, a, b, c, type);
}

double edge_edge_distance_squared(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1,
                                  EdgeEdgeDistanceType type) {
  using T = EdgeEdgeDistanceType;
  switch (type) {
    case T::kA0B0:
      return point_point_distance_squared(a0, b0);
    case T::kA0B1:
      return point_point_distance_squared(a0, b1);
    case T::kA1B0:
      return point_point_distance_squared(a1, b0);
    case T::kA1B1:
      return point_point_distance_squared(a1, b1);
    case T::kA0EdgeB:
      return point_line_distance_squared(a0, b0, b1);
    case T::kA1EdgeB:
      return point_line_distance_squared(a1, b0, b1);
    case T::kB0EdgeA:
      return point_line_distance_squared(b0, a0, a1);
    case T::kB1EdgeA:
      return point_line_distance_squared(b1, a0, a1);
    case T::kInterior:
      return line_line_distance_squared(a0, a1, b0, b1);
  }
  assert(false && "unknown edge-edge distance type");
  return 0.0;
}

StencilDerivatives<4> edge_edge_distance_squared_derivatives(const Vec3& a0, const Vec3& a1,
                                                             const Vec3& b0, const Vec3& b1,
                                                             EdgeEdgeDistanceType type) {
  return edge_edge_formula<WithHessian>(a0, a1, b0, b1, type);
}

StencilGradient<4> edge_edge_distance_squared_gradient(const Vec3& a0, const Vec3& a1,
                                                       const Vec3& b0, const Vec3& b1,
                                                       EdgeEdgeDistanceType type) {
  return edge_edge_formula<GradientOnly>(a0, a1, b0, b1, type);
}

}  // namespace animkit
