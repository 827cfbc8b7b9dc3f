#pragma once
// Flat triangle meshes of a square sheet, for the tests of cloth cut from meshes.
#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "animkit/cloth/grid_cloth.h"
#include "animkit/core/triangle_mesh.h"

namespace animkit::testing_support {

/// The grid cloth's sheet as a mesh: vertex grid_index(cells, i, j) at (i s, height,
/// j s - size / 2), s = size / cells, each cell split along its (i, j)-(i+1, j+1) diagonal as
/// make_grid_cloth's triangles. `jitter` > 0 moves the interior vertices by up to jitter s
/// along x and z (seeded: the same mesh every run), an irregular triangulation of the square.
inline TriangleMesh square_sheet(int cells, double size, double height, double jitter,
                                 unsigned seed = 1) {
  TriangleMesh mesh;
  const double s = size / cells;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter * s, jitter * s);
  for (int i = 0; i <= cells; ++i) {
    for (int j = 0; j <= cells; ++j) {
      Vec3 p(i * s, height, j * s - 0.5 * size);
      if (jitter > 0.0 && i > 0 && i < cells && j > 0 && j < cells) {
        p.x() += u(rng);
        p.z() += u(rng);
      }
      mesh.vertices.push_back(p);
    }
  }
  const auto id = [cells](int i, int j) { return grid_index(cells, i, j); };
  for (int i = 0; i < cells; ++i) {
    for (int j = 0; j < cells; ++j) {
      mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return mesh;
}

/// Equilateral triangles of side size / cells in the plane y = 0: cells + 1 rows of cells + 1
/// vertices along x, the odd rows shifted by half a side.
inline TriangleMesh equilateral_sheet(int cells, double size) {
  TriangleMesh mesh;
  const double s = size / cells, h = s * std::sqrt(3.0) / 2.0;
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i)
      mesh.vertices.emplace_back(i * s + (j % 2) * 0.5 * s - 0.5 * size, 0.0, j * h - 0.5 * size);
  }
  const auto id = [cells](int i, int j) { return j * (cells + 1) + i; };
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      if (j % 2 == 0) {
        mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        mesh.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      }
    }
  }
  return mesh;
}

/// `mesh` as OBJ text (1-based indices).
inline std::string obj_text(const TriangleMesh& mesh) {
  std::ostringstream out;
  out.precision(17);
  for (const Vec3& v : mesh.vertices) out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const auto& t : mesh.triangles)
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  return out.str();
}

}  // namespace animkit::testing_support
