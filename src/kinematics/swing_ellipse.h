#pragma once
// The nearest point of a filled ellipse, for elliptical swing cones (joint_limits.cpp).
#include <Eigen/Core>

namespace animkit {

/// The point of {(x/a)^2 + (y/b)^2 <= 1} nearest to `point` (Euclidean); `point` itself when
/// inside. Semi-axes a, b >= 0; a zero semi-axis makes the ellipse a segment (or a point).
Eigen::Vector2d nearest_in_ellipse(const Eigen::Vector2d& point, double a, double b);

}  // namespace animkit
