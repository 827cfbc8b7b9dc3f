#pragma once
// Where a contact pair is closest: the two points whose distance the barrier measures, for
// drawing contacts and for tests. Closest points on a triangle and between segments follow
// Ericson, Real-Time Collision Detection (2005), sections 5.1.5 and 5.1.9.
#include <array>

#include "animkit/core/types.h"
#include "contact_pair.h"

namespace animkit {

/// The point of triangle (a, b, c) nearest p (by Voronoi regions of its vertices, edges and
/// face). A degenerate triangle (sides parallel within kParallelTolerance) gives the nearest
/// point of its edges.
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// The points of segments (a0, a1) and (b0, b1) nearest each other: [on a, on b]. Parallel
/// segments give one of the nearest pairs.
std::array<Vec3, 2> closest_points_of_segments(const Vec3& a0, const Vec3& a1, const Vec3& b0,
                                               const Vec3& b1);

/// The pair's closest points at positions p (p[i] the position of vertices[i]), `ground` the
/// plane's height: [on the first primitive (the point, edge a, the particle), on the second
/// (the triangle, edge b, the ground)]; for a sphere's pair, its surface's point toward the
/// triangle in place of its centre. Their distance is the pair's unmollified distance.
std::array<Vec3, 2> contact_closest_points(const ContactPair& pair, const std::array<Vec3, 4>& p,
                                           double ground);

}  // namespace animkit
