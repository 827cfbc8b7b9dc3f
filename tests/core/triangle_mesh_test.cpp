#include "animkit/core/triangle_mesh.h"

#include <gtest/gtest.h>

#include <limits>

namespace animkit {
namespace {

TriangleMesh quad() {
  return {{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}, {{0, 1, 2}, {0, 2, 3}}};
}

TEST(TriangleMesh, AValidMeshHasNoProblem) {
  EXPECT_FALSE(quad().validate());
}

TEST(TriangleMesh, NamesTheFirstProblem) {
  TriangleMesh empty;
  EXPECT_EQ(empty.validate()->message, "the mesh has no triangles");
  TriangleMesh nan = quad();
  nan.vertices[2].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(nan.validate()->message, "mesh vertex 2 has a non-finite coordinate");
  TriangleMesh out_of_range = quad();
  out_of_range.triangles[1][2] = 4;
  EXPECT_EQ(out_of_range.validate()->message,
            "mesh triangle 1 refers to vertex 4 but the mesh has 4 vertices");
  TriangleMesh repeated = quad();
  repeated.triangles[0] = {0, 1, 1};
  EXPECT_EQ(repeated.validate()->message, "mesh triangle 0 repeats a vertex");
  TriangleMesh flat = quad();
  flat.vertices[2] = Vec3(2, 0, 0);
  EXPECT_EQ(flat.validate()->message, "mesh triangle 0 has zero area");
}

}  // namespace
}  // namespace animkit
