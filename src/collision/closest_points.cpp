#include "animkit/collision/closest_points.h"

#include <algorithm>
#include <cmath>

#include "animkit/collision/distance_type.h"

namespace animkit {

namespace {

// A divisor for num / den that is never zero nor small enough for the quotient to overflow:
// where a compiler divides before it tests den (clang does, and the tests trap floating-point
// exceptions), the division it does must be harmless.
double safe_divisor(double num, double den) {
  return std::max({den, 1e-300 * std::abs(num), 1e-300});
}

// num / den clamped to [0, 1]; 0 for a degenerate denominator (a zero-length edge).
double clamped_ratio(double num, double den) {
  const double ratio = std::clamp(num / safe_divisor(num, den), 0.0, 1.0);
  return den > 0.0 ? ratio : 0.0;
}

}  // namespace

// Ericson 2005, section 5.1.5: the Voronoi regions of the vertices, then the edges, then the
// face.
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
    const double v = vb / safe_divisor(vb, sum), w = vc / safe_divisor(vc, sum);
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

// Ericson 2005, section 5.1.9.
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

double closest_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  return clamped_ratio((p - a).dot(b - a), (b - a).squaredNorm());
}

}  // namespace animkit
