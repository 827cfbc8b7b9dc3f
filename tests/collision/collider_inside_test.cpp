#include "animkit/collision/collider_inside.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "animkit/collision/collider_surface.h"

namespace animkit {
namespace {

// Uniform points in the cube [-extent, extent]^3, the same on every run.
std::vector<Vec3> random_points(double extent, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-extent, extent);
  std::vector<Vec3> points(count);
  for (Vec3& p : points) p = Vec3(u(rng), u(rng), u(rng));
  return points;
}

TEST(ColliderInside, AnalyticShapesAgreeWithTheirDefinitions) {
  const SphereShape sphere{0.8};
  const BoxShape box{Vec3(0.3, 0.9, 0.6)};
  const CapsuleShape capsule{0.35, 0.5};
  for (const Vec3& p : random_points(1.5, 4000, 7)) {
    EXPECT_EQ(inside(PlaneShape{}, p), p.y() < 0);
    EXPECT_EQ(inside(sphere, p), p.squaredNorm() < 0.64);
    EXPECT_EQ(inside(box, p),
              std::abs(p.x()) < 0.3 && std::abs(p.y()) < 0.9 && std::abs(p.z()) < 0.6);
    // A capsule is a cylinder and two balls.
    const double r2 = capsule.radius * capsule.radius;
    const bool in_cylinder = std::abs(p.y()) <= 0.5 && p.x() * p.x() + p.z() * p.z() < r2;
    const bool in_caps =
        (p - Vec3(0, 0.5, 0)).squaredNorm() < r2 || (p - Vec3(0, -0.5, 0)).squaredNorm() < r2;
    EXPECT_EQ(inside(capsule, p), in_cylinder || in_caps) << p.transpose();
  }
}

TEST(ColliderInside, SignedDistancesAtKnownPoints) {
  const BoxShape box{Vec3(1, 2, 3)};
  EXPECT_DOUBLE_EQ(signed_distance(box, Vec3(0, 0, 0)), -1.0);  // nearest face x = +-1
  EXPECT_DOUBLE_EQ(signed_distance(box, Vec3(0, 2.5, 0)), 0.5);
  EXPECT_DOUBLE_EQ(signed_distance(box, Vec3(4, 6, 3)), 5.0);  // from the edge (1, 2, z)
  EXPECT_DOUBLE_EQ(signed_distance(box, Vec3(1, 0, 0)), 0.0);
  EXPECT_FALSE(inside(box, Vec3(1, 0, 0)));  // on the surface: not inside
  const CapsuleShape capsule{0.5, 1.0};
  EXPECT_DOUBLE_EQ(signed_distance(capsule, Vec3(0, 3, 0)), 1.5);
  EXPECT_DOUBLE_EQ(signed_distance(capsule, Vec3(2, 0.3, 0)), 1.5);
  EXPECT_DOUBLE_EQ(signed_distance(capsule, Vec3(0, 0.3, 0)), -0.5);
  EXPECT_DOUBLE_EQ(signed_distance(SphereShape{2}, Vec3(0, 3, 4)), 3.0);
  EXPECT_DOUBLE_EQ(signed_distance(PlaneShape{}, Vec3(5, -0.25, 7)), -0.25);
}

TEST(ColliderInside, ATessellatedSphereMeshAgreesWithTheSphereAwayFromItsSurface) {
  const double radius = 0.8;
  const MeshShape mesh{collider_surface(SphereShape{radius}, 3)};
  int tested = 0;
  for (const Vec3& p : random_points(1.2, 1500, 11)) {
    const double r = p.norm();
    if (std::abs(r - radius) < 0.02) continue;  // the inscribed mesh is within 0.005 of it
    ++tested;
    EXPECT_EQ(inside(mesh, p), r < radius) << p.transpose();
    // Not just on the right side of 1/2: 1 inside, 0 outside, to rounding.
    EXPECT_NEAR(winding_number(mesh.mesh, p), r < radius ? 1.0 : 0.0, 1e-9);
  }
  EXPECT_GT(tested, 1400);
}

TEST(ColliderInside, WindingNumberOfANonConvexMesh) {
  // Two unit cubes' surfaces, one reversed inside the other's larger copy: a hollow shell.
  TriangleMesh outer = collider_surface(BoxShape{Vec3::Constant(1.0)}, 1);
  const TriangleMesh inner = collider_surface(BoxShape{Vec3::Constant(0.5)}, 0);
  const int offset = static_cast<int>(outer.vertices.size());
  outer.vertices.insert(outer.vertices.end(), inner.vertices.begin(), inner.vertices.end());
  for (const auto& t : inner.triangles) {
    outer.triangles.push_back({t[0] + offset, t[2] + offset, t[1] + offset});
  }
  const MeshShape shell{outer};
  EXPECT_FALSE(inside(shell, Vec3(0, 0, 0)));  // in the cavity
  EXPECT_TRUE(inside(shell, Vec3(0.75, 0.1, -0.2)));
  EXPECT_FALSE(inside(shell, Vec3(1.5, 0, 0)));
  EXPECT_NEAR(winding_number(shell.mesh, Vec3(0, 0, 0)), 0.0, 1e-12);
}

TEST(ColliderInside, PointsOnAMeshDoNotTrap) {
  // The test runner traps FP exceptions: a vertex, an edge point and a face point are fine.
  const TriangleMesh box = collider_surface(BoxShape{}, 0);
  for (const Vec3& p : {box.vertices[0], Vec3(0.5, 0.5, 0.0), Vec3(0.5, 0.1, 0.2)}) {
    const double w = winding_number(box, p);
    EXPECT_TRUE(std::isfinite(w));
    EXPECT_GE(w, -1e-12);
    EXPECT_LE(w, 1.0 + 1e-12);
  }
}

}  // namespace
}  // namespace animkit
