#pragma once
// An audit of intersections that shares no code with animkit's contact solver: CGAL's exact
// predicates (Epick kernel) on the triangles as they are. Used by the contact tests and the
// drape benchmark to count frames that pass through a collider or through themselves.
#include <array>
#include <vector>

#include "animkit/core/triangle_mesh.h"
#include "animkit/core/types.h"

namespace animkit::audit {

/// Pairs of triangles of the mesh that intersect, besides what they legitimately share (a
/// common vertex or edge of adjacent triangles). Exact.
int count_self_intersections(const TriangleMesh& mesh);

/// Whether a triangle of `a` intersects (touches or crosses) a triangle of `b`. Exact.
bool meshes_intersect(const TriangleMesh& a, const TriangleMesh& b);

}  // namespace animkit::audit
