#include "swing_ellipse.h"

#include <algorithm>
#include <cmath>

namespace animkit {

Eigen::Vector2d nearest_in_ellipse(const Eigen::Vector2d& point, double a, double b) {
  // By symmetry solve in the first quadrant and restore the signs.
  const double p = std::abs(point.x()), q = std::abs(point.y());
  const auto signed_point = [&](double x, double y) {
    return Eigen::Vector2d(std::copysign(x, point.x()), std::copysign(y, point.y()));
  };
  if (a == 0.0 || b == 0.0) {  // a segment along the other axis, or the origin
    return signed_point(std::min(p, a), std::min(q, b));
  }
  if ((p * b) * (p * b) + (q * a) * (q * a) <= (a * b) * (a * b)) return point;
  // The nearest boundary point X of an outside point P has P - X along the normal at X:
  // X = (a^2 p / (t + a^2), b^2 q / (t + b^2)) for the root t > 0 of
  //   F(t) = (a p / (t + a^2))^2 + (b q / (t + b^2))^2 - 1,
  // which decreases for t > 0, with F(0) > 0 (P outside) and F(T) <= 0 at
  // T = |(a p, b q)| (each term is at most (a p / T)^2, resp. (b q / T)^2). Bisection keeps
  // F(hi) <= 0, so the point returned is never outside (Eberly, "Distance from a point to an
  // ellipse", 2011, solves the same equation by bisection).
  const auto f = [&](double t) {
    const double x = a * p / (t + a * a), y = b * q / (t + b * b);
    return x * x + y * y - 1.0;
  };
  double lo = 0.0, hi = std::hypot(a * p, b * q);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;  // the bracket is down to adjacent doubles
    (f(mid) > 0.0 ? lo : hi) = mid;
  }
  return signed_point(a * a * p / (hi + a * a), b * b * q / (hi + b * b));
}

}  // namespace animkit
