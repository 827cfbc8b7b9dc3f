#pragma once
// The closest points of two primitives (Ericson, "Real-Time Collision Detection", 2005,
// chapter 5), as weights of their vertices: what friction's tangent frame and the CCD's
// separating direction are built from.
#include <array>

#include "animkit/core/types.h"

namespace animkit {

/// Barycentric coordinates (of a, b, c) of the point of triangle (a, b, c) closest to p. A
/// degenerate (zero-area) triangle that reaches the face case takes its nearest edge instead.
std::array<double, 3> closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                          const Vec3& c);

/// Parameters (s, t) of the closest points a0 + s (a1 - a0) and b0 + t (b1 - b0), clamped to
/// the segments; parallel edges take s = 0 (at the same distance).
std::array<double, 2> closest_on_edges(const Vec3& a0, const Vec3& a1, const Vec3& b0,
                                       const Vec3& b1);

/// Parameter s of the point a + s (b - a) of segment (a, b) closest to p; 0 for a zero-length
/// segment.
double closest_on_segment(const Vec3& p, const Vec3& a, const Vec3& b);

}  // namespace animkit
