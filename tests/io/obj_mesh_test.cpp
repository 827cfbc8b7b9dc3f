#include "animkit/io/obj_mesh.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../support/temp_files.h"

namespace animkit {
namespace {

std::string error_of(std::string_view text) {
  const auto mesh = parse_obj_mesh(text, "m.obj");
  EXPECT_FALSE(mesh);
  return mesh ? std::string("(no error)") : mesh.error().message;
}

TEST(ObjMesh, ReadsVerticesAndTrianglesIgnoringEverythingElse) {
  const auto mesh = parse_obj_mesh(
      "# a unit square\nmtllib sq.mtl\no square\nv 0 0 0\nv 1 0 0\r\nv 1 0 1 1.0\n"
      "v 0 0 1 0.5 0.5 0.5\nvt 0 0\nvn 0 1 0\ns off\nusemtl cloth\nf 1 2 3\n\n  f\t1 3 4  \n",
      "sq.obj");
  ASSERT_TRUE(mesh) << mesh.error().message;
  ASSERT_EQ(mesh->vertices.size(), 4u);
  EXPECT_EQ(mesh->vertices[2], Vec3(1, 0, 1));
  ASSERT_EQ(mesh->triangles.size(), 2u);
  EXPECT_EQ(mesh->triangles[0], (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(mesh->triangles[1], (std::array<int, 3>{0, 2, 3}));
}

TEST(ObjMesh, FanTriangulatesPolygonsAndReadsEveryCornerForm) {
  const auto mesh = parse_obj_mesh(
      "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nf 1/1 2/2/2 3//3 4/4/4 5\n", "p.obj");
  ASSERT_TRUE(mesh) << mesh.error().message;
  ASSERT_EQ(mesh->triangles.size(), 3u);
  EXPECT_EQ(mesh->triangles[0], (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(mesh->triangles[1], (std::array<int, 3>{0, 2, 3}));
  EXPECT_EQ(mesh->triangles[2], (std::array<int, 3>{0, 3, 4}));
}

TEST(ObjMesh, NegativeIndicesCountBackFromTheLastVertexRead) {
  const auto mesh =
      parse_obj_mesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 1 1 0\nf -3/1/1 -1 -2\n", "n.obj");
  ASSERT_TRUE(mesh) << mesh.error().message;
  ASSERT_EQ(mesh->triangles.size(), 2u);
  EXPECT_EQ(mesh->triangles[0], (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(mesh->triangles[1], (std::array<int, 3>{1, 3, 2}));
}

TEST(ObjMesh, PositiveIndicesMayNameVerticesFurtherDown) {
  const auto mesh = parse_obj_mesh("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", "late.obj");
  ASSERT_TRUE(mesh) << mesh.error().message;
  EXPECT_EQ(mesh->triangles.size(), 1u);
}

TEST(ObjMesh, ErrorsNameTheFileAndTheLine) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_EQ(error_of("v 0 0 0\nv 1 x 0\n"),
            "m.obj line 2: expected a vertex 'v x y z' of three numbers, got 'v 1 x 0'");
  EXPECT_EQ(error_of("v 0 0\n"),
            "m.obj line 1: expected a vertex 'v x y z' of three numbers, got 'v 0 0'");
  EXPECT_EQ(error_of("v 0 0 0 zz\n"),
            "m.obj line 1: expected a vertex 'v x y z' of three numbers, got 'v 0 0 0 zz'");
  EXPECT_EQ(error_of("v nan 0 0\n"), "m.obj line 1: the vertex is not finite, got 'v nan 0 0'");
  EXPECT_EQ(error_of("v 1 inf 0\n"), "m.obj line 1: the vertex is not finite, got 'v 1 inf 0'");
  EXPECT_EQ(error_of("v 1 1e999 0\n"), "m.obj line 1: the vertex is not finite, got 'v 1 1e999 0'");
  EXPECT_EQ(error_of(tri + "f 1 2 x\n"),
            "m.obj line 4: expected face corners 'v', 'v/vt', 'v//vn' or 'v/vt/vn' with an "
            "integer v, got 'f 1 2 x'");
  EXPECT_EQ(error_of(tri + "f 1.5 2 3\n"),
            "m.obj line 4: expected face corners 'v', 'v/vt', 'v//vn' or 'v/vt/vn' with an "
            "integer v, got 'f 1.5 2 3'");
  EXPECT_EQ(error_of(tri + "f 99999999999 2 3\n"),
            "m.obj line 4: expected face corners 'v', 'v/vt', 'v//vn' or 'v/vt/vn' with an "
            "integer v, got 'f 99999999999 2 3'");
  EXPECT_EQ(error_of(tri + "f 0 1 2\n"),
            "m.obj line 4: vertex index 0 (OBJ indices start at 1), got 'f 0 1 2'");
  EXPECT_EQ(error_of(tri + "f 1 2 -4\n"),
            "m.obj line 4: vertex index -4 reaches before the first vertex (3 read so far), got "
            "'f 1 2 -4'");
  EXPECT_EQ(error_of(tri + "f 1 2 4\n"),
            "m.obj line 4: vertex index 4 is beyond the file's 3 vertices");
  EXPECT_EQ(error_of(tri + "f 1 2\n"),
            "m.obj line 4: a face needs at least three vertices, got 'f 1 2'");
  EXPECT_EQ(error_of(tri + "f 1 2 2\n"), "m.obj line 4: the face repeats a vertex");
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"),
            "m.obj line 4: the face has a triangle of zero area (vertices 1, 2, 3)");
  EXPECT_EQ(error_of(tri + std::string("f 1 2\0 3\n", 9)),
            "m.obj line 4: holds a NUL byte (not a text file?): 'f 1 2\\x00 3'");
  EXPECT_EQ(error_of(""), "m.obj: no vertices and no faces (an empty OBJ file?)");
  EXPECT_EQ(error_of("# only a comment\n\n"),
            "m.obj: no vertices and no faces (an empty OBJ file?)");
  EXPECT_EQ(error_of(tri), "m.obj: no faces (expected lines 'f a b c')");
}

TEST(ObjMesh, ReadsAFileAndNamesItInErrors) {
  const std::filesystem::path dir = testing_support::fresh_dir("obj_mesh");
  {
    std::ofstream(dir / "quad.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    std::ofstream(dir / "bad.obj") << "v 0 0 0\nf 1 2 3\n";
  }
  const auto mesh = read_obj_mesh(dir / "quad.obj");
  ASSERT_TRUE(mesh) << mesh.error().message;
  EXPECT_EQ(mesh->triangles.size(), 2u);
  const auto bad = read_obj_mesh(dir / "bad.obj");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().message,
            (dir / "bad.obj").string() + " line 2: vertex index 2 is beyond the file's 1 vertices");
  const auto missing = read_obj_mesh(dir / "none.obj");
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().message, (dir / "none.obj").string() + ": no such file");
}

}  // namespace
}  // namespace animkit
