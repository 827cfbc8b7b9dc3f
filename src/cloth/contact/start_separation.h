#pragma once
// Whether a configuration can start a contact simulation. IPC's guarantee is inductive: every
// step ends intersection-free because it starts so (Li et al. 2020, section 5), and its barrier
// is finite only for pairs at a positive distance. A cloth that starts through an obstacle or
// through itself has no barrier between the crossing primitives at all (a small sphere through
// a triangle's middle is far from every vertex and edge of it) and would run on, crossed, as a
// success; one that starts touching has an infinite barrier. Both are refused up front.
#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>

#include "contact_candidates.h"

namespace animkit {

/// Names obstacle vertex v (an index into the obstacles' vertices) for a message, e.g.
/// "collider 'ball'".
using ObstacleNamer = std::function<std::string(int obstacle_vertex)>;

/// The first reason, in a fixed order, why the cloth at x (3N, world, m) cannot start against
/// the obstacles where they are now: a point-triangle or edge-edge pair (cloth-obstacle, or
/// cloth-cloth with self-contact) closer than `min_gap` (m), a cloth edge through an obstacle
/// triangle, an obstacle edge through a cloth triangle, or (with self-contact) a cloth edge
/// through a cloth triangle it does not share a vertex with. None when the start is clear.
/// The message names the particles and the obstacle, e.g. "the cloth's edge between particles
/// 4 and 5 passes through collider 'pea'".
std::optional<std::string> find_start_overlap(const ContactGeometry& geometry,
                                              const Eigen::VectorXd& x, double min_gap,
                                              const ObstacleNamer& obstacle_name);

/// Whether segment (p, q) passes through the inside of triangle (a, b, c): the segment's ends
/// strictly on either side of the triangle's plane and the segment's line strictly inside the
/// triangle's three edges (signed volumes, each taken as zero below a 1e-10 relative size, the
/// rounding of coplanar points). Touching cases (a zero volume) are not crossings: they are at
/// distance zero, which the point-triangle and edge-edge distances report.
bool segment_crosses_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                              const Vec3& c);

}  // namespace animkit
