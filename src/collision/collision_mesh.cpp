#include "animkit/collision/collision_mesh.h"

#include <algorithm>
#include <string>

namespace animkit {

Result<CollisionMesh> build_collision_mesh(int vertex_count,
                                           std::span<const std::array<int, 3>> triangles) {
  if (vertex_count < 0) {
    return fail("collision mesh vertex count must be >= 0, got " + std::to_string(vertex_count));
  }
  CollisionMesh mesh;
  mesh.vertex_count = vertex_count;
  mesh.triangles.assign(triangles.begin(), triangles.end());
  mesh.edges.reserve(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const std::array<int, 3>& tri = triangles[t];
    for (int k = 0; k < 3; ++k) {
      if (tri[k] < 0 || tri[k] >= vertex_count) {
        return fail("triangle " + std::to_string(t) + " has vertex " + std::to_string(tri[k]) +
                    " outside [0, " + std::to_string(vertex_count) + ")");
      }
      const int next = tri[(k + 1) % 3];
      if (tri[k] == next) {
        return fail("triangle " + std::to_string(t) + " repeats vertex " + std::to_string(next));
      }
    }
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      mesh.edges.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  std::sort(mesh.edges.begin(), mesh.edges.end());
  mesh.edges.erase(std::unique(mesh.edges.begin(), mesh.edges.end()), mesh.edges.end());
  return mesh;
}

}  // namespace animkit
