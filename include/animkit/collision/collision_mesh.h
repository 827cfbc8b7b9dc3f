#pragma once
// The primitives of a triangle mesh that contact acts on: its vertices, its unique edges and its
// triangles (IPC's point-triangle and edge-edge pairs are built from these, Li et al. 2020,
// section 4). Built once from the triangles; positions live apart (a 3N vector, like the
// cloth's state), so one mesh serves every configuration.
#include <array>
#include <span>
#include <vector>

#include "animkit/core/result.h"

namespace animkit {

/// A mesh's contact primitives: its vertex count, unique edges and triangles (no positions).
/// Make one with build_collision_mesh().
struct CollisionMesh {
  int vertex_count = 0;  ///< number of vertices, >= 0; positions come as 3 * vertex_count doubles
  /// Unique edges of the triangles, each (lower index, higher index), sorted.
  std::vector<std::array<int, 2>> edges;
  /// The triangles as given (vertex indices in [0, vertex_count)).
  std::vector<std::array<int, 3>> triangles;
};

/// Builds the mesh of `triangles` over `vertex_count` >= 0 vertices. Fails naming the first
/// problem: "triangle 3 has vertex 12 outside [0, 10)", "triangle 5 repeats vertex 2".
Result<CollisionMesh> build_collision_mesh(int vertex_count,
                                           std::span<const std::array<int, 3>> triangles);

}  // namespace animkit
