#include "contact_points.h"

#include <algorithm>

#include "animkit/collision/distance_type.h"

namespace animkit {

namespace {

Vec3 closest_point_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  if (length2 == 0.0) return a;
  return a + std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) * ab;
}

}  // namespace

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Ericson 5.1.5: test p against the Voronoi regions of a, b, c, then of the edges, by the
  // signs of dot products (d1..d6) and of the barycentric numerators (va, vb, vc).
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  if (ab.cross(ac).squaredNorm() <= kParallelTolerance * ab.squaredNorm() * ac.squaredNorm()) {
    // Degenerate (its sides parallel): the regions' signs are rounding noise; its edges hold
    // all its points.
    const Vec3 candidates[3] = {closest_point_on_segment(p, a, b),
                                closest_point_on_segment(p, b, c),
                                closest_point_on_segment(p, c, a)};
    return *std::min_element(std::begin(candidates), std::end(candidates),
                             [&](const Vec3& u, const Vec3& v) {
                               return (u - p).squaredNorm() < (v - p).squaredNorm();
                             });
  }
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double sum = va + vb + vc;  // |ab x ac|^2 > 0: not degenerate
  return a + (vb / sum) * ab + (vc / sum) * ac;
}

std::array<Vec3, 2> closest_points_of_segments(const Vec3& a0, const Vec3& a1, const Vec3& b0,
                                               const Vec3& b1) {
  // Ericson 5.1.9: minimize |a0 + s da - b0 - t db|^2 over s, t in [0, 1]: the unconstrained
  // s of the two lines clamped, t from s, and s recomputed when t had to be clamped.
  const Vec3 da = a1 - a0, db = b1 - b0, r = a0 - b0;
  const double a = da.squaredNorm(), e = db.squaredNorm(), f = db.dot(r);
  double s = 0.0, t = 0.0;
  if (a == 0.0 && e == 0.0) return {a0, b0};
  if (a == 0.0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = da.dot(r);
    if (e == 0.0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = da.dot(db), denom = a * e - b * b;  // >= 0; zero when parallel
      s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return {a0 + s * da, b0 + t * db};
}

std::array<Vec3, 2> contact_closest_points(const ContactPair& pair, const std::array<Vec3, 4>& p,
                                           double ground) {
  switch (pair.kind) {
    case ContactKind::point_triangle: {
      const Vec3 q = closest_point_on_triangle(p[0], p[1], p[2], p[3]);
      if (pair.thickness > 0.0) {
        // A sphere's centre: its surface's point toward the triangle.
        const Vec3 toward = q - p[0];
        const double distance = toward.norm();
        if (distance > 0.0) return {p[0] + (pair.thickness / distance) * toward, q};
      }
      return {p[0], q};
    }
    case ContactKind::edge_edge:
      return closest_points_of_segments(p[0], p[1], p[2], p[3]);
    case ContactKind::ground:
      return {p[0], Vec3(p[0].x(), ground, p[0].z())};
  }
  return {p[0], p[0]};
}

}  // namespace animkit
