#include "animkit/cloth/mesh_edges.h"

#include <algorithm>
#include <cassert>
#include <string>

namespace animkit {

Result<std::vector<MeshEdge>> mesh_edges(const TriangleMesh& mesh) {
  // Every (lower vertex, higher vertex, triangle), sorted: an edge's triangles end up adjacent,
  // in mesh order.
  std::vector<std::array<int, 3>> sides;
  sides.reserve(3 * mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      sides.push_back({std::min(a, b), std::max(a, b), static_cast<int>(t)});
    }
  }
  std::sort(sides.begin(), sides.end());
  std::vector<MeshEdge> edges;
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while (j < sides.size() && sides[j][0] == sides[i][0] && sides[j][1] == sides[i][1]) ++j;
    if (j - i > 2) {
      return fail("mesh edge between vertices " + std::to_string(sides[i][0]) + " and " +
                  std::to_string(sides[i][1]) + " is shared by " + std::to_string(j - i) +
                  " triangles (" + std::to_string(sides[i][2]) + ", " +
                  std::to_string(sides[i + 1][2]) + ", " + std::to_string(sides[i + 2][2]) +
                  (j - i > 3 ? ", ..." : "") +
                  "): a cloth needs a manifold mesh, at most two triangles per edge");
    }
    edges.push_back({{sides[i][0], sides[i][1]}, {sides[i][2], j - i == 2 ? sides[i + 1][2] : -1}});
    i = j;
  }
  return edges;
}

int opposite_vertex(const TriangleMesh& mesh, int t, const MeshEdge& edge) {
  for (int v : mesh.triangles[static_cast<std::size_t>(t)]) {
    if (v != edge.vertices[0] && v != edge.vertices[1]) return v;
  }
  assert(false && "the triangle is not on the edge");
  return -1;
}

}  // namespace animkit
