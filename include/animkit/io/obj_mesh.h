#pragma once
// Triangle meshes from Wavefront OBJ files (what Blender, Maya and most tools export): the
// shape a cloth is cut from (`animkit cloth --mesh`). Only geometry is read:
// - `v x y z [w]`: a vertex (w, or any further numbers such as vertex colours, ignored);
// - `f a b c ...`: a polygon of 3 or more vertices, fan-triangulated (a b c, a c d, ...); each
//   corner is `v`, `v/vt`, `v//vn` or `v/vt/vn`, of which only v is used; indices start at 1,
//   and a negative index counts back from the last vertex read so far (-1: the last one);
// - everything else (comments, vt, vn, o, g, s, usemtl, mtllib, l, ...) is ignored.
#include <cstdint>
#include <filesystem>
#include <string_view>

#include "animkit/core/result.h"
#include "animkit/core/triangle_mesh.h"

namespace animkit {

/// Largest OBJ file read: some tens of millions of triangles, far beyond a cloth's size.
constexpr std::uintmax_t kMaxObjFileBytes = 1024u << 20;

/// The mesh in OBJ `text`. `name` (the file's) starts every error, which names the line and
/// quotes it (quote_input): a malformed or non-finite number, a vertex with fewer than three
/// coordinates, a face with fewer than three corners, an index 0 or out of range, a NUL byte;
/// then an empty file, a file with no faces, and whatever TriangleMesh::validate() refuses
/// (e.g. a triangle of zero area).
Result<TriangleMesh> parse_obj_mesh(std::string_view text, std::string_view name);

/// parse_obj_mesh of the file's bytes; also errors for a missing, unreadable or huge file.
Result<TriangleMesh> read_obj_mesh(const std::filesystem::path& path);

}  // namespace animkit
