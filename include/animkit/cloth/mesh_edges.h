#pragma once
// The edges of a triangle mesh and, per edge, the triangles it borders (the edge-adjacency a
// cloth's springs and bending elements are built on).
#include <array>
#include <vector>

#include "animkit/core/result.h"
#include "animkit/core/triangle_mesh.h"

namespace animkit {

/// One edge of a triangle mesh and the one or two triangles it borders.
struct MeshEdge {
  std::array<int, 2> vertices{};  ///< the edge's vertices, lower index first
  /// The triangles (indices into TriangleMesh::triangles) on either side, in mesh order;
  /// triangles[1] is -1 on a border edge (one triangle).
  std::array<int, 2> triangles{-1, -1};

  /// Whether two triangles share the edge (false on the border).
  bool interior() const { return triangles[1] >= 0; }
};

/// Every edge of `mesh` once, sorted by (vertices[0], vertices[1]). Error: an edge shared by
/// three or more triangles (a non-manifold mesh, which no cloth surface is), naming the edge and
/// three of its triangles. Expects a mesh TriangleMesh::validate() accepts.
Result<std::vector<MeshEdge>> mesh_edges(const TriangleMesh& mesh);

/// The vertex of triangle `t` of `mesh` that is not on `edge` (one of its triangles).
int opposite_vertex(const TriangleMesh& mesh, int t, const MeshEdge& edge);

}  // namespace animkit
