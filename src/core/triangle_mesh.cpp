#include "animkit/core/triangle_mesh.h"

#include <string>

#include "animkit/core/validation.h"

namespace animkit {

std::optional<Error> TriangleMesh::validate() const {
  if (triangles.empty()) return Error{"the mesh has no triangles"};
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (!is_finite(vertices[i]))
      return Error{"mesh vertex " + std::to_string(i) + " has a non-finite coordinate"};
  }
  const int n = static_cast<int>(vertices.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    const std::string name = "mesh triangle " + std::to_string(t);
    for (int v : tri) {
      if (v < 0 || v >= n) {
        return Error{name + " refers to vertex " + std::to_string(v) + " but the mesh has " +
                     std::to_string(n) + " vertices"};
      }
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
      return Error{name + " repeats a vertex"};
    const Vec3 normal =
        (vertices[tri[1]] - vertices[tri[0]]).cross(vertices[tri[2]] - vertices[tri[0]]);
    if (!(normal.norm() > 0.0)) return Error{name + " has zero area"};
  }
  return std::nullopt;
}

}  // namespace animkit
