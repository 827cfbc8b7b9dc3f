#include "animkit/scene/draw_list.h"

#include <cmath>
#include <numbers>

namespace animkit {

namespace {
Vec3f to_float(const Vec3& v) {
  return v.cast<float>();
}
}  // namespace

void DrawList::clear() {
  triangles.clear();
  lines.clear();
  points.clear();
}

void DrawList::add_triangle(const Vec3& a, const Vec3& b, const Vec3& c, Rgba front, Rgba back) {
  Vec3 n = (b - a).cross(c - a);
  const double length = n.norm();
  n = length > 0.0 ? Vec3(n / length) : Vec3::UnitY();
  const Vec3 p[3] = {a, b, c};
  const Vec3 normals[3] = {n, n, n};
  add_triangle(p, normals, front, back);
}

void DrawList::add_triangle(const Vec3 (&p)[3], const Vec3 (&n)[3], Rgba front, Rgba back) {
  for (int k = 0; k < 3; ++k) triangles.push_back({to_float(p[k]), to_float(n[k]), front, back});
}

void DrawList::add_line(const Vec3& a, const Vec3& b, Rgba color, float width_px) {
  lines.push_back({to_float(a), to_float(b), color, width_px});
}

void DrawList::add_polyline(const std::vector<Vec3>& polyline, Rgba color, float width_px) {
  for (std::size_t i = 1; i < polyline.size(); ++i) {
    add_line(polyline[i - 1], polyline[i], color, width_px);
  }
}

void DrawList::add_point(const Vec3& p, Rgba color, float size_px) {
  points.push_back({to_float(p), color, size_px});
}

void DrawList::add_bone_box(const Vec3& a, const Vec3& b, double thickness, Rgba color) {
  const Vec3 axis = b - a;
  if (axis.norm() == 0.0) return;
  // Two unit vectors across the bone: any perpendicular, then the one completing the frame.
  const Vec3 u = axis.unitOrthogonal() * (0.5 * thickness);
  const Vec3 v = axis.normalized().cross(u);
  const Vec3 corner[8] = {a - u - v, a + u - v, a + u + v, a - u + v,
                          b - u - v, b + u - v, b + u + v, b - u + v};
  // Each face as four corner indices, counter-clockwise seen from outside.
  static constexpr int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                      {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  for (const auto& f : faces) {
    add_triangle(corner[f[0]], corner[f[1]], corner[f[2]], color, color);
    add_triangle(corner[f[0]], corner[f[2]], corner[f[3]], color, color);
  }
}

void DrawList::add_sphere(const Vec3& center, double radius, Rgba color, int slices, int stacks) {
  const auto direction = [&](int i, int j) {
    const double theta = std::numbers::pi * j / stacks;  // from +y down to -y
    const double phi = 2.0 * std::numbers::pi * i / slices;
    return Vec3(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
  };
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      const Vec3 d[4] = {direction(i, j), direction(i, j + 1), direction(i + 1, j + 1),
                         direction(i + 1, j)};
      const Vec3 p[4] = {center + radius * d[0], center + radius * d[1], center + radius * d[2],
                         center + radius * d[3]};
      const Vec3 t1[3] = {p[0], p[1], p[2]}, n1[3] = {d[0], d[1], d[2]};
      const Vec3 t2[3] = {p[0], p[2], p[3]}, n2[3] = {d[0], d[2], d[3]};
      add_triangle(t1, n1, color, color);
      add_triangle(t2, n2, color, color);
    }
  }
}

void DrawList::add_ground_grid(double height, int cells, double spacing, double axis_length) {
  const double half = 0.5 * cells * spacing;
  for (int i = 0; i <= cells; ++i) {
    const double s = -half + i * spacing;
    add_line(Vec3(s, height, -half), Vec3(s, height, half), palette::grid);
    add_line(Vec3(-half, height, s), Vec3(half, height, s), palette::grid);
  }
  const Vec3 origin(0.0, height, 0.0);
  add_line(origin, origin + axis_length * Vec3::UnitX(), {0.85f, 0.15f, 0.15f, 1.0f}, 2.0f);
  add_line(origin, origin + axis_length * Vec3::UnitY(), {0.15f, 0.65f, 0.15f, 1.0f}, 2.0f);
  add_line(origin, origin + axis_length * Vec3::UnitZ(), {0.15f, 0.25f, 0.85f, 1.0f}, 2.0f);
}

Eigen::AlignedBox3d DrawList::bounds() const {
  Eigen::AlignedBox3d box;
  for (const auto& v : triangles) box.extend(v.position.cast<double>());
  for (const auto& l : lines) {
    box.extend(l.a.cast<double>());
    box.extend(l.b.cast<double>());
  }
  for (const auto& p : points) box.extend(p.position.cast<double>());
  return box;
}

}  // namespace animkit
