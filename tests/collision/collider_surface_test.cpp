#include "animkit/collision/collider_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "animkit/collision/collider_inside.h"
#include "shared_constants.h"

namespace animkit {
namespace {

using testing_support::kPi;

// Closed and consistently oriented: every directed edge appears once and its reverse once, so
// each undirected edge is shared by exactly two triangles that traverse it oppositely.
void expect_closed(const TriangleMesh& mesh, const std::string& what) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    ASSERT_EQ(count, 1) << what << ": edge " << edge.first << "-" << edge.second;
    ASSERT_EQ(directed.count({edge.second, edge.first}), 1u)
        << what << ": edge " << edge.first << "-" << edge.second << " is on a hole";
  }
  // Watertight and a sphere topologically: V - E + F = 2.
  const auto v = static_cast<long>(mesh.vertices.size());
  const auto e = static_cast<long>(surface_edges(mesh).size());
  const auto f = static_cast<long>(mesh.triangles.size());
  EXPECT_EQ(v - e + f, 2) << what;
  EXPECT_EQ(2 * e, 3 * f) << what;
}

// Divergence theorem: the volume is the sum of the tetrahedra from the origin to each
// triangle, positive when the triangles are counter-clockwise seen from outside.
double signed_volume(const TriangleMesh& mesh) {
  double six_volume = 0.0;
  for (const auto& t : mesh.triangles) {
    six_volume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]]));
  }
  return six_volume / 6.0;
}

double max_distance_off(const ColliderShape& shape, const TriangleMesh& mesh) {
  double worst = 0.0;
  for (const Vec3& v : mesh.vertices) {
    const double d = std::visit(
        [&v](const auto& s) {
          if constexpr (std::is_same_v<std::decay_t<decltype(s)>, MeshShape>) {
            return 0.0;
          } else {
            return signed_distance(s, v);
          }
        },
        shape);
    worst = std::max(worst, std::abs(d));
  }
  return worst;
}

struct SolidCase {
  std::string name;
  ColliderShape shape;
  double volume;  // analytic, m^3
};

std::vector<SolidCase> solids() {
  const double r = 0.7;
  const Vec3 h(0.3, 0.5, 0.9);
  return {
      {"sphere", SphereShape{r}, 4.0 / 3.0 * kPi * r * r * r},
      {"box", BoxShape{h}, 8.0 * h.prod()},
      {"capsule", CapsuleShape{0.2, 0.6}, kPi * 0.04 * 1.2 + 4.0 / 3.0 * kPi * 0.008},
      {"short capsule", CapsuleShape{0.5, 0.01}, kPi * 0.25 * 0.02 + 4.0 / 3.0 * kPi * 0.125},
  };
}

TEST(ColliderSurface, EverySolidIsClosedOutwardAndOnItsShape) {
  for (const SolidCase& solid : solids()) {
    for (int level = kMinTessellation; level <= 4; ++level) {
      const std::string what = solid.name + " at level " + std::to_string(level);
      const TriangleMesh mesh = collider_surface(solid.shape, level);
      ASSERT_FALSE(mesh.validate()) << what << ": " << mesh.validate()->message;
      expect_closed(mesh, what);
      EXPECT_GT(signed_volume(mesh), 0.0) << what;
      EXPECT_LT(max_distance_off(solid.shape, mesh), 1e-14) << what;
    }
  }
}

TEST(ColliderSurface, VolumeApproachesTheShapesAsTessellationGrows) {
  for (const SolidCase& solid : solids()) {
    double previous_error = 1.0;
    for (int level = kMinTessellation; level <= 5; ++level) {
      const double volume = signed_volume(collider_surface(solid.shape, level));
      const double error = (solid.volume - volume) / solid.volume;
      if (solid.name == "box") {
        EXPECT_NEAR(error, 0.0, 1e-13) << "level " << level;  // exact up to rounding
        continue;
      }
      // Inscribed (every vertex on the surface of a convex shape), and closer at each level:
      // the gap between chord and arc shrinks about fourfold when the angular step halves.
      EXPECT_GT(error, 0.0) << solid.name << " at level " << level;
      EXPECT_LT(error, 0.5 * previous_error) << solid.name << " at level " << level;
      previous_error = error;
    }
    if (solid.name != "box") {
      EXPECT_LT(previous_error, 2e-3) << solid.name << " at level 5";
    }
  }
}

TEST(ColliderSurface, TriangleCountsFollowTheLevel) {
  for (int level = 0; level <= 3; ++level) {
    const int factor = 1 << (2 * level);
    EXPECT_EQ(collider_surface(SphereShape{1.0}, level).triangles.size(), 20u * factor);
    EXPECT_EQ(collider_surface(BoxShape{}, level).triangles.size(), 12u * factor);
  }
  // Out-of-range levels are clamped (validate() refuses them in a description).
  EXPECT_EQ(collider_surface(SphereShape{1.0}, -3).triangles.size(), 20u);
}

TEST(ColliderSurface, TheTriangleCountIsKnownBeforeTheSurfaceIsMade) {
  const TriangleMesh tetrahedron{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                 {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
  const ColliderShape shapes[] = {SphereShape{0.3}, BoxShape{Vec3(1, 0.1, 2)},
                                  CapsuleShape{0.2, 0.5}, CapsuleShape{0.01, 10.0},
                                  CapsuleShape{1.0, 0.01}, PlaneShape{}, MeshShape{tetrahedron},
                                  // long and thin enough to overflow a length / segment quotient
                                  CapsuleShape{1e-305, 1e6}};
  for (const ColliderShape& shape : shapes) {
    for (int level = 0; level <= 4; ++level) {
      EXPECT_EQ(surface_triangle_count(shape, level),
                collider_surface(shape, level).triangles.size())
          << shape.index() << " at level " << level;
    }
  }
}

TEST(ColliderSurface, ThePlaneIsASquareFacingUp) {
  const TriangleMesh square = collider_surface(PlaneShape{4.0}, 3);
  ASSERT_EQ(square.triangles.size(), 2u);
  ASSERT_FALSE(square.validate());
  double area = 0.0;
  for (const auto& t : square.triangles) {
    const Vec3 n = (square.vertices[t[1]] - square.vertices[t[0]])
                       .cross(square.vertices[t[2]] - square.vertices[t[0]]);
    EXPECT_GT(n.y(), 0.0);
    area += 0.5 * n.norm();
  }
  EXPECT_DOUBLE_EQ(area, 16.0);
  for (const Vec3& v : square.vertices) {
    EXPECT_EQ(v.y(), 0.0);
    EXPECT_EQ(v.cwiseAbs().maxCoeff(), 2.0);
  }
}

TEST(ColliderSurface, AMeshIsUsedAsGiven) {
  const TriangleMesh tetrahedron{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                 {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
  const TriangleMesh mesh = collider_surface(MeshShape{tetrahedron}, 2);
  EXPECT_EQ(mesh.vertices, tetrahedron.vertices);
  EXPECT_EQ(mesh.triangles, tetrahedron.triangles);
  expect_closed(mesh, "tetrahedron");
  EXPECT_NEAR(signed_volume(mesh), 1.0 / 6.0, 1e-15);
}

TEST(MeshEdges, EachEdgeOnceSorted) {
  const TriangleMesh tetrahedron{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                 {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
  const std::vector<std::array<int, 2>> expected = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  EXPECT_EQ(surface_edges(tetrahedron), expected);
}

}  // namespace
}  // namespace animkit
