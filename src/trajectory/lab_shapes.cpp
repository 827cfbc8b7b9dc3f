#include "animkit/trajectory/lab_shapes.h"

#include <array>
#include <cmath>
#include <numbers>

namespace animkit {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Appends the points a + (b - a) * k / count for k in [0, count): one edge of a polygon,
// its end left to the next edge, as the lab's loops do.
void append_edge(std::vector<Vec3>& out, const Vec3& a, const Vec3& b, int count) {
  for (int k = 0; k < count; ++k) out.push_back(a + (b - a) * (static_cast<double>(k) / count));
}

// A closed polygon through `corners`, with edge e taking the points [splits[e], splits[e+1]).
std::vector<Vec3> polygon(std::span<const Vec3> corners, std::span<const int> splits) {
  std::vector<Vec3> out;
  out.reserve(static_cast<std::size_t>(splits.back()));
  for (std::size_t e = 0; e + 1 < splits.size(); ++e) {
    append_edge(out, corners[e], corners[(e + 1) % corners.size()], splits[e + 1] - splits[e]);
  }
  return out;
}

std::vector<Vec3> circle() {
  constexpr int n = 150;
  constexpr double radius = 0.6;
  std::vector<Vec3> out;
  for (int i = 0; i < n; ++i) {
    const double t = kTwoPi * i / n;
    out.emplace_back(radius * std::cos(t), 0.0, radius * std::sin(t));
  }
  return out;
}

std::vector<Vec3> square() {
  constexpr int n = 150;
  constexpr double h = 0.2;  // half of the side 0.4
  const std::array<Vec3, 4> corners{Vec3(-h, 0, h), Vec3(h, 0, h), Vec3(h, 0, -h), Vec3(-h, 0, -h)};
  const std::array<int, 5> splits{0, n / 4, 2 * n / 4, 3 * n / 4, n};
  return polygon(corners, splits);
}

std::vector<Vec3> heart() {
  constexpr int n = 150;
  std::vector<Vec3> out;
  for (int i = 0; i < n; ++i) {
    const double t = kTwoPi * i / n;
    const double r = 0.5 * (1.0 - std::sin(t));
    out.emplace_back(r * std::cos(t), 0.0, r * std::sin(t));
  }
  return out;
}

std::vector<Vec3> triangle() {
  constexpr int n = 150;
  const std::array<Vec3, 3> corners{Vec3(0, 0, 0), Vec3(0.5, 0, 0), Vec3(0, 0, 0.5)};
  const std::array<int, 4> splits{0, n / 3, 2 * n / 3, n};
  return polygon(corners, splits);
}

std::vector<Vec3> star() {
  constexpr int n = 400;
  constexpr double radius = 0.4;
  std::array<Vec3, 5> on_circle;
  for (int i = 0; i < 5; ++i) {
    const double t = kTwoPi * i / 5;
    on_circle[i] = Vec3(radius * std::cos(t), 0.0, radius * std::sin(t));
  }
  // Every second vertex of the pentagon: 4 -> 1 -> 3 -> 0 -> 2 -> 4.
  const std::array<Vec3, 5> corners{on_circle[4], on_circle[1], on_circle[3], on_circle[0],
                                    on_circle[2]};
  const std::array<int, 6> splits{0, n / 5, 2 * n / 5, 3 * n / 5, 4 * n / 5, n};
  return polygon(corners, splits);
}

}  // namespace

std::string_view to_string(LabShape shape) {
  switch (shape) {
    case LabShape::circle:
      return "circle";
    case LabShape::square:
      return "square";
    case LabShape::heart:
      return "heart";
    case LabShape::triangle:
      return "triangle";
    case LabShape::star:
      return "star";
  }
  return "unknown";
}

std::span<const LabShape> all_lab_shapes() {
  static constexpr std::array shapes{LabShape::circle, LabShape::square, LabShape::heart,
                                     LabShape::triangle, LabShape::star};
  return shapes;
}

std::optional<LabShape> parse_lab_shape(std::string_view name) {
  for (LabShape shape : all_lab_shapes()) {
    if (name == to_string(shape)) return shape;
  }
  return std::nullopt;
}

std::vector<Vec3> lab_shape_targets(LabShape shape) {
  switch (shape) {
    case LabShape::circle:
      return circle();
    case LabShape::square:
      return square();
    case LabShape::heart:
      return heart();
    case LabShape::triangle:
      return triangle();
    case LabShape::star:
      return star();
  }
  return {};
}

}  // namespace animkit
