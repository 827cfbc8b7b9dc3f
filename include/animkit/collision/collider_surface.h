#pragma once
// The triangle mesh contact, drawing and export use for a shape (local frame). Every solid's
// surface is closed (each edge shared by exactly two triangles), watertight (neighbours share
// vertices, not just positions), oriented outward (counter-clockwise seen from outside) and has
// every vertex on the analytic surface, so the mesh is inscribed in the shape.
#include <array>
#include <cstddef>
#include <vector>

#include "animkit/collision/collider_shape.h"

namespace animkit {

/// Tessellation levels collider_surface() accepts: each level quadruples the triangles (level
/// 6 already makes 81 920 for a sphere).
inline constexpr int kMinTessellation = 0, kMaxTessellation = 6;

/// The shape's surface at `tessellation` level L (in [kMinTessellation, kMaxTessellation]):
/// - sphere: an icosahedron subdivided L times (20 * 4^L triangles);
/// - box: each face a grid of 2^L x 2^L squares (12 * 4^L triangles), so contacts on a large
///   face are resolved by more than its two triangles;
/// - capsule: 8 * 2^L segments around the axis, 2 * 2^L rings per hemisphere (the same angular
///   step), and the cylinder cut into rings about as long as a segment is wide (at most
///   64 * 2^L rings);
/// - mesh: the mesh as given (L ignored);
/// - plane: the square of side display_size centred on the origin in y = 0, normal +y, for
///   drawing and export only (not closed: contact treats the plane as a half-space).
TriangleMesh collider_surface(const ColliderShape& shape, int tessellation);

/// How many triangles collider_surface(shape, tessellation) makes, without making them (so a
/// scene can be refused before it allocates).
std::size_t surface_triangle_count(const ColliderShape& shape, int tessellation);

/// Each undirected edge of the mesh once, as (smaller index, larger index), sorted: the edges
/// edge-edge contact runs over.
std::vector<std::array<int, 2>> surface_edges(const TriangleMesh& mesh);

}  // namespace animkit
