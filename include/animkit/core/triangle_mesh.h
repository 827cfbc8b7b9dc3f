#pragma once
// A triangle mesh as plain data: the shape a cloth is cut from (--mesh), a collider's surface,
// what OBJ files hold. Shared by cloth, collision and io.
#include <array>
#include <optional>
#include <vector>

#include "animkit/core/result.h"
#include "animkit/core/types.h"

namespace animkit {

/// A triangle mesh as plain data: vertex positions and index triples (see the file overview).
struct TriangleMesh {
  std::vector<Vec3> vertices;  ///< positions, scene units (m for physical scenes)
  /// Vertex indices (0-based), counter-clockwise seen from the side the normal points to.
  std::vector<std::array<int, 3>> triangles;

  /// The first problem: no triangles, a non-finite vertex, an index out of range, a triangle
  /// that repeats a vertex or has zero area. Nothing when the mesh is usable.
  std::optional<Error> validate() const;
};

}  // namespace animkit
