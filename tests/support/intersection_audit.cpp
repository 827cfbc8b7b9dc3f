#include "intersection_audit.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <iterator>
#include <stdexcept>
#include <utility>

namespace animkit::audit {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace pmp = CGAL::Polygon_mesh_processing;

Mesh to_cgal(const TriangleMesh& mesh) {
  std::vector<Point> points;
  points.reserve(mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) points.emplace_back(v.x(), v.y(), v.z());
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    faces.push_back({static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]),
                     static_cast<std::size_t>(t[2])});
  }
  if (!pmp::is_polygon_soup_a_polygon_mesh(faces))
    throw std::invalid_argument("intersection audit: the triangles are not a manifold mesh");
  Mesh out;
  pmp::polygon_soup_to_polygon_mesh(points, faces, out);
  return out;
}

}  // namespace

int count_self_intersections(const TriangleMesh& mesh) {
  const Mesh m = to_cgal(mesh);
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
  pmp::self_intersections(m, std::back_inserter(pairs));
  return static_cast<int>(pairs.size());
}

bool meshes_intersect(const TriangleMesh& a, const TriangleMesh& b) {
  return pmp::do_intersect(to_cgal(a), to_cgal(b));
}

}  // namespace animkit::audit
