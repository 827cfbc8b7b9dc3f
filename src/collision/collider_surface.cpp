#include "animkit/collision/collider_surface.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace animkit {

namespace {

using Triangle = std::array<int, 3>;

// A convex surface around the origin is outward where each triangle's normal points away from
// the origin; flipping the ones that do not saves writing every face's winding by hand.
void orient_outward(TriangleMesh& mesh) {
  for (Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3 normal = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
    if (normal.dot(a + mesh.vertices[t[1]] + mesh.vertices[t[2]]) < 0.0) std::swap(t[1], t[2]);
  }
}

// Icosahedron (12 vertices (0, +-1, +-phi) and their cyclic permutations), each triangle cut
// into four at its edges' midpoints `levels` times, every vertex pushed out onto the sphere.
TriangleMesh icosphere(double radius, int levels) {
  const double phi = std::numbers::phi;
  TriangleMesh mesh;
  mesh.vertices = {{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0},
                   {0, -1, phi}, {0, 1, phi}, {0, -1, -phi}, {0, 1, -phi},
                   {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
  for (Vec3& v : mesh.vertices) v.normalize();
  mesh.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  orient_outward(mesh);
  for (int level = 0; level < levels; ++level) {
    // One midpoint per edge, shared by the edge's two triangles: the mesh stays watertight.
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto [it, inserted] =
          midpoints.try_emplace(key, static_cast<int>(mesh.vertices.size()));
      if (inserted) mesh.vertices.push_back((mesh.vertices[a] + mesh.vertices[b]).normalized());
      return it->second;
    };
    std::vector<Triangle> finer;
    finer.reserve(4 * mesh.triangles.size());
    for (const auto& [a, b, c] : mesh.triangles) {
      const int ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      finer.insert(finer.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    mesh.triangles = std::move(finer);
  }
  for (Vec3& v : mesh.vertices) v *= radius;
  return mesh;
}

// The boundary of the lattice {0..n}^3 scaled onto the box: vertices keyed by their lattice
// point, so faces meeting at an edge share its vertices.
TriangleMesh box_surface(const Vec3& half, int levels) {
  const int n = 1 << levels;
  TriangleMesh mesh;
  std::map<std::array<int, 3>, int> index;
  auto vertex = [&](const std::array<int, 3>& p) {
    const auto [it, inserted] = index.try_emplace(p, static_cast<int>(mesh.vertices.size()));
    if (inserted) {
      Vec3 v;
      for (int k = 0; k < 3; ++k) v[k] = half[k] * (2.0 * p[k] / n - 1.0);
      mesh.vertices.push_back(v);
    }
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis) {
    // (u, v, axis) is right-handed, so a square counter-clockwise in (u, v) faces +axis.
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int side : {0, n}) {
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          std::array<int, 4> corner;
          const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
          for (int k = 0; k < 4; ++k) {
            std::array<int, 3> p;
            p[axis] = side;
            p[u] = i + du[k];
            p[v] = j + dv[k];
            corner[k] = vertex(p);
          }
          if (side == 0) std::swap(corner[1], corner[3]);  // faces -axis: reverse the winding
          mesh.triangles.push_back({corner[0], corner[1], corner[2]});
          mesh.triangles.push_back({corner[0], corner[2], corner[3]});
        }
      }
    }
  }
  return mesh;
}

// Rings of vertices from the top pole to the bottom one: the top hemisphere's rings, the
// cylinder's inner rings, the bottom hemisphere's rings; neighbouring rings joined by quads.
// Cylinder rings about a segment apart (so its triangles are not needles), at most 64 * 2^L
// of them for a long thin capsule.
int capsule_cylinder_rings(double radius, double half_length, int levels) {
  const int around = 8 << levels;
  const double segment = radius * 2.0 * std::numbers::pi / around;
  const double max_rings = 64 << levels;
  // Compared before dividing: a radius of 1e-305 would overflow the quotient.
  if (2.0 * half_length >= max_rings * segment) return static_cast<int>(max_rings);
  return static_cast<int>(std::max(std::ceil(2.0 * half_length / segment), 1.0));
}

TriangleMesh capsule_surface(double radius, double half_length, int levels) {
  const int around = 8 << levels;
  const int per_cap = 2 << levels;
  const double step = std::numbers::pi / 2.0 / per_cap;  // = 2 pi / around
  const int cylinder = capsule_cylinder_rings(radius, half_length, levels);
  // Each ring as (height, distance from the axis).
  std::vector<std::pair<double, double>> rings;
  for (int k = 1; k < per_cap; ++k) {
    rings.emplace_back(half_length + radius * std::cos(k * step), radius * std::sin(k * step));
  }
  for (int j = 0; j <= cylinder; ++j) {
    rings.emplace_back(half_length - 2.0 * half_length * j / cylinder, radius);
  }
  for (int k = per_cap - 1; k >= 1; --k) {
    rings.emplace_back(-half_length - radius * std::cos(k * step), radius * std::sin(k * step));
  }
  TriangleMesh mesh;
  mesh.vertices.emplace_back(0.0, half_length + radius, 0.0);
  for (const auto& [y, rho] : rings) {
    for (int i = 0; i < around; ++i) {
      const double theta = 2.0 * std::numbers::pi * i / around;
      mesh.vertices.emplace_back(rho * std::cos(theta), y, rho * std::sin(theta));
    }
  }
  const int bottom = static_cast<int>(mesh.vertices.size());
  mesh.vertices.emplace_back(0.0, -half_length - radius, 0.0);
  auto at = [&](int ring, int i) { return 1 + ring * around + i % around; };
  const int last = static_cast<int>(rings.size()) - 1;
  for (int i = 0; i < around; ++i) {
    mesh.triangles.push_back({0, at(0, i + 1), at(0, i)});
    for (int r = 0; r < last; ++r) {
      const int a = at(r, i), b = at(r + 1, i), c = at(r + 1, i + 1), d = at(r, i + 1);
      mesh.triangles.push_back({a, c, b});
      mesh.triangles.push_back({a, d, c});
    }
    mesh.triangles.push_back({bottom, at(last, i), at(last, i + 1)});
  }
  return mesh;
}

TriangleMesh plane_square(double size) {
  const double h = 0.5 * size;
  // Counter-clockwise seen from +y.
  return {{{-h, 0, -h}, {-h, 0, h}, {h, 0, h}, {h, 0, -h}}, {{0, 1, 2}, {0, 2, 3}}};
}

}  // namespace

TriangleMesh collider_surface(const ColliderShape& shape, int tessellation) {
  const int level = std::clamp(tessellation, kMinTessellation, kMaxTessellation);
  struct Build {
    int level;
    TriangleMesh operator()(const PlaneShape& s) const { return plane_square(s.display_size); }
    TriangleMesh operator()(const SphereShape& s) const { return icosphere(s.radius, level); }
    TriangleMesh operator()(const BoxShape& s) const { return box_surface(s.half_extents, level); }
    TriangleMesh operator()(const CapsuleShape& s) const {
      return capsule_surface(s.radius, s.half_length, level);
    }
    TriangleMesh operator()(const MeshShape& s) const { return s.mesh; }
  };
  return std::visit(Build{level}, shape);
}

std::size_t surface_triangle_count(const ColliderShape& shape, int tessellation) {
  const int level = std::clamp(tessellation, kMinTessellation, kMaxTessellation);
  const std::size_t quadruple = std::size_t{1} << (2 * level);  // 4^level
  struct Count {
    int level;
    std::size_t quadruple;
    std::size_t operator()(const PlaneShape&) const { return 2; }
    std::size_t operator()(const SphereShape&) const { return 20 * quadruple; }
    std::size_t operator()(const BoxShape&) const { return 12 * quadruple; }
    std::size_t operator()(const CapsuleShape& s) const {
      // Rings: 2 (2^(L+1) - 1) on the caps and the cylinder's rings + 1; quads between
      // consecutive rings and a fan at each pole, around = 8 * 2^L each.
      const std::size_t around = std::size_t{8} << level;
      const std::size_t rings = 2 * ((std::size_t{2} << level) - 1) +
                                capsule_cylinder_rings(s.radius, s.half_length, level) + 1;
      return around * (2 * (rings - 1) + 2);
    }
    std::size_t operator()(const MeshShape& s) const { return s.mesh.triangles.size(); }
  };
  return std::visit(Count{level, quadruple}, shape);
}

std::vector<std::array<int, 2>> surface_edges(const TriangleMesh& mesh) {
  std::vector<std::array<int, 2>> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const auto [a, b] = std::minmax(t[k], t[(k + 1) % 3]);
      edges.push_back({a, b});
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

}  // namespace animkit
