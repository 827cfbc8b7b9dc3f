#include "start_separation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "../stacked_vectors.h"

namespace animkit {

namespace {

// "1.2e-09": distances in messages.
std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3g", value);
  return text;
}

std::string particles(int a, int b) {
  return "particles " + std::to_string(a) + " and " + std::to_string(b);
}

std::string particles(const std::array<int, 3>& t) {
  return "particles " + std::to_string(t[0]) + ", " + std::to_string(t[1]) + " and " +
         std::to_string(t[2]);
}

// The sign of tetrahedron (a, b, c, d)'s volume: +1, -1, or 0 where the volume is below
// kFlat of the product of its edges from a, above rounding's size for coplanar points (a flat
// sheet's own edges and triangles, which must not count as crossing). A crossing flatter than
// that (a segment end within 1e-10 of the edge lengths of the plane, or a segment passing that
// close to a triangle's edge) is not reported as one; at the usual scales it is also closer
// than the minimum gap and refused as touching.
int orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  constexpr double kFlat = 1e-10;
  const Vec3 ab = b - a, ac = c - a, ad = d - a;
  const double volume = ab.cross(ac).dot(ad);
  const double scale = ab.norm() * ac.norm() * ad.norm();
  if (std::abs(volume) <= kFlat * scale) return 0;
  return volume > 0.0 ? 1 : -1;
}

// One side of a crossing test: an edge or a triangle of the cloth or of the obstacles, with
// its box (world space).
struct Boxed {
  Vec3 lo, hi;
  int index;  // into the mesh's edges or triangles
};

template <std::size_t K>
Boxed boxed(const std::array<int, K>& vertices, int index,
            const std::function<Vec3(int)>& position) {
  Boxed b{position(vertices[0]), position(vertices[0]), index};
  for (std::size_t k = 1; k < K; ++k) {
    b.lo = b.lo.cwiseMin(position(vertices[k]));
    b.hi = b.hi.cwiseMax(position(vertices[k]));
  }
  return b;
}

bool overlap(const Boxed& a, const Boxed& b) {
  return (a.lo.array() <= b.hi.array()).all() && (b.lo.array() <= a.hi.array()).all();
}

// The axis along which the boxes' lower corners spread most: a sweep along it keeps few boxes
// open at once (a sheet in the plane x = 0 would keep all of them open along x).
int sweep_axis(const std::vector<Boxed>& a, const std::vector<Boxed>& b) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto* list : {&a, &b}) {
    for (const Boxed& box : *list) {
      lo = lo.cwiseMin(box.lo);
      hi = hi.cwiseMax(box.lo);
    }
  }
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  return axis;
}

// Calls f(edge index, triangle index) for every edge box overlapping a triangle box: a sweep
// over both lists sorted by their boxes' lower corner along one axis (each list keeps the boxes
// the sweep has entered and whose upper corner it has not yet passed).
template <class F>
void for_each_overlap(std::vector<Boxed> edges, std::vector<Boxed> triangles, F f) {
  if (edges.empty() || triangles.empty()) return;
  const int axis = sweep_axis(edges, triangles);
  const auto by_lo = [axis](const Boxed& a, const Boxed& b) {
    return a.lo[axis] < b.lo[axis] || (a.lo[axis] == b.lo[axis] && a.index < b.index);
  };
  std::sort(edges.begin(), edges.end(), by_lo);
  std::sort(triangles.begin(), triangles.end(), by_lo);
  std::vector<const Boxed*> open_edges, open_triangles;
  const auto close_before = [axis](std::vector<const Boxed*>& open, double at) {
    std::erase_if(open, [axis, at](const Boxed* b) { return b->hi[axis] < at; });
  };
  std::size_t e = 0, t = 0;
  while (e < edges.size() || t < triangles.size()) {
    const bool edge_next =
        t == triangles.size() || (e < edges.size() && !by_lo(triangles[t], edges[e]));
    if (edge_next) {
      const Boxed& edge = edges[e++];
      close_before(open_triangles, edge.lo[axis]);
      for (const Boxed* triangle : open_triangles)
        if (overlap(edge, *triangle)) f(edge.index, triangle->index);
      open_edges.push_back(&edge);
    } else {
      const Boxed& triangle = triangles[t++];
      close_before(open_edges, triangle.lo[axis]);
      for (const Boxed* edge : open_edges)
        if (overlap(*edge, triangle)) f(edge->index, triangle.index);
      open_triangles.push_back(&triangle);
    }
  }
}

bool shares_vertex(const std::array<int, 2>& edge, const std::array<int, 3>& triangle) {
  for (int e : edge)
    for (int t : triangle)
      if (e == t) return true;
  return false;
}

// Why a pair closer than the minimum gap is refused, naming both sides.
std::string touching(const ContactPair& pair, int cloth_vertices, double gap, double min_gap,
                     const ObstacleNamer& obstacle_name) {
  const auto& v = pair.vertices;
  const bool other_is_cloth = v[3] < cloth_vertices;
  std::string what;
  if (pair.kind == ContactKind::point_triangle) {
    if (pair.thickness > 0.0 && !(gap > 0.0)) {
      // A sphere's centre, the triangle reaching into the sphere.
      return obstacle_name(v[0] - cloth_vertices) + " passes through the cloth's triangle of " +
             particles({v[1], v[2], v[3]}) + " at the start";
    }
    if (v[0] >= cloth_vertices) {
      what = obstacle_name(v[0] - cloth_vertices) + " touches the cloth's triangle of " +
             particles({v[1], v[2], v[3]});
    } else if (other_is_cloth) {
      what = "the cloth touches itself: particle " + std::to_string(v[0]) +
             " and the triangle of " + particles({v[1], v[2], v[3]});
    } else {
      what =
          "particle " + std::to_string(v[0]) + " touches " + obstacle_name(v[1] - cloth_vertices);
    }
  } else if (other_is_cloth) {
    what = "the cloth touches itself: its edges between " + particles(v[0], v[1]) + " and " +
           "between " + particles(v[2], v[3]);
  } else {
    what = "the cloth's edge between " + particles(v[0], v[1]) + " touches " +
           obstacle_name(v[2] - cloth_vertices);
  }
  return what + " at the start (" + number(gap) + " m apart; contact needs them at least " +
         number(min_gap) + " m apart)";
}

}  // namespace

bool segment_crosses_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b,
                              const Vec3& c) {
  const int sp = orientation(a, b, c, p), sq = orientation(a, b, c, q);
  if (sp == 0 || sq == 0 || sp == sq) return false;
  const int ab = orientation(p, q, a, b), bc = orientation(p, q, b, c),
            ca = orientation(p, q, c, a);
  return ab != 0 && ab == bc && bc == ca;
}

std::optional<std::string> find_start_overlap(const ContactGeometry& geometry,
                                              const Eigen::VectorXd& x, double min_gap,
                                              const ObstacleNamer& obstacle_name) {
  const int n = geometry.cloth_vertices();
  const auto position = [&](int v) {
    return v < n ? at(x, v) : at(geometry.obstacle_positions, v - n);
  };

  // Touching: every pair the broad phase finds within the minimum gap, measured.
  ContactPairFinder finder;
  std::vector<ContactPair> pairs;
  if (auto ok = finder.gather(geometry, x, nullptr, min_gap, std::nullopt, pairs); !ok)
    return ok.error().message;
  for (const ContactPair& pair : pairs) {
    std::array<Vec3, 4> p;
    for (int i = 0; i < 4; ++i) p[i] = position(pair.vertices[i]);
    const double gap = std::sqrt(contact_distance_squared(pair, p, 0.0));
    if (gap < min_gap) return touching(pair, n, gap, min_gap, obstacle_name);
  }

  // Crossing: every edge through a triangle of the other side (obstacle primitives in the
  // contact index space start at n).
  const std::function<Vec3(int)> cloth_position = [&](int v) { return position(v); };
  const std::function<Vec3(int)> obstacle_position = [&](int v) { return position(n + v); };
  const auto boxes_of = [](const auto& primitives, const std::function<Vec3(int)>& where) {
    std::vector<Boxed> boxes;
    boxes.reserve(primitives.size());
    for (std::size_t i = 0; i < primitives.size(); ++i)
      boxes.push_back(boxed(primitives[i], static_cast<int>(i), where));
    return boxes;
  };
  const CollisionMesh& cloth = geometry.cloth;
  const CollisionMesh& obstacles = geometry.obstacles;
  const auto crosses = [](const auto& edge, const auto& triangle, const auto& where) {
    return segment_crosses_triangle(where.first(edge[0]), where.first(edge[1]),
                                    where.second(triangle[0]), where.second(triangle[1]),
                                    where.second(triangle[2]));
  };
  std::optional<std::string> found;
  const auto first = [&found](std::string message) {
    if (!found) found = std::move(message);
  };
  for_each_overlap(
      boxes_of(cloth.edges, cloth_position), boxes_of(obstacles.triangles, obstacle_position),
      [&](int e, int t) {
        const auto& edge = cloth.edges[e];
        if (!found &&
            crosses(edge, obstacles.triangles[t], std::pair(cloth_position, obstacle_position))) {
          first("the cloth's edge between " + particles(edge[0], edge[1]) + " passes through " +
                obstacle_name(obstacles.triangles[t][0]) + " at the start");
        }
      });
  if (found) return found;
  for_each_overlap(
      boxes_of(obstacles.edges, obstacle_position), boxes_of(cloth.triangles, cloth_position),
      [&](int e, int t) {
        const auto& triangle = cloth.triangles[t];
        if (!found &&
            crosses(obstacles.edges[e], triangle, std::pair(obstacle_position, cloth_position))) {
          first(obstacle_name(obstacles.edges[e][0]) + " passes through the cloth's triangle of " +
                particles(triangle) + " at the start");
        }
      });
  if (found || !geometry.self_contact) return found;
  for_each_overlap(boxes_of(cloth.edges, cloth_position), boxes_of(cloth.triangles, cloth_position),
                   [&](int e, int t) {
                     const auto& edge = cloth.edges[e];
                     const auto& triangle = cloth.triangles[t];
                     if (!found && !shares_vertex(edge, triangle) &&
                         crosses(edge, triangle, std::pair(cloth_position, cloth_position))) {
                       first("the cloth passes through itself at the start: its edge between " +
                             particles(edge[0], edge[1]) + " through its triangle of " +
                             particles(triangle));
                     }
                   });
  return found;
}

}  // namespace animkit
