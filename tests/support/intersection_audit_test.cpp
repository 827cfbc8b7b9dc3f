// The intersection audit itself: it must find what is there and nothing else, or the contact
// tests that rely on it prove nothing.
#include "intersection_audit.h"

#include <gtest/gtest.h>

#include "animkit/cloth/grid_cloth.h"

namespace animkit::audit {
namespace {

TriangleMesh grid_mesh(int cells) {
  const ClothDesc desc = make_grid_cloth({.cells = cells});
  TriangleMesh mesh;
  for (const ParticleDesc& p : desc.particles) mesh.vertices.push_back(p.position);
  mesh.triangles = desc.triangles;
  return mesh;
}

TEST(IntersectionAudit, AFlatGridDoesNotIntersectItself) {
  EXPECT_EQ(count_self_intersections(grid_mesh(6)), 0);
}

TEST(IntersectionAudit, AGridFoldedThroughItselfDoes) {
  // Bend the sheet's far half up and back through the near half: z mirrored past x = 1.
  TriangleMesh mesh = grid_mesh(8);
  for (Vec3& v : mesh.vertices) {
    if (v.x() > 1.0) v = Vec3(2.0 - v.x(), v.y() + 0.3 * (v.x() - 1.0) - 0.1, v.z());
  }
  EXPECT_GT(count_self_intersections(mesh), 0);
}

TEST(IntersectionAudit, TouchingCountsAndSeparatedDoesNot) {
  const TriangleMesh a{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 1)}, {{0, 2, 1}}};
  TriangleMesh b{{Vec3(0.2, -0.5, 0.2), Vec3(0.2, 0.5, 0.2), Vec3(0.3, 0.0, -0.5)}, {{0, 1, 2}}};
  EXPECT_TRUE(meshes_intersect(a, b));  // b pierces a
  for (Vec3& v : b.vertices) v.y() += 0.5;
  EXPECT_TRUE(meshes_intersect(a, b));  // b's corner lies on a: exact, so it counts
  for (Vec3& v : b.vertices) v.y() += 1e-12;
  EXPECT_FALSE(meshes_intersect(a, b));  // a hair's breadth above
}

}  // namespace
}  // namespace animkit::audit
