#include "animkit/io/obj_mesh.h"

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "animkit/core/quote.h"
#include "animkit/io/file_bytes.h"
#include "held_fp_exceptions.h"
#include "text_lines.h"

namespace animkit {

namespace {

// All of `token` as strtod reads it ("1e-3", "+2", "nan", "inf"). Copied: strtod needs a NUL.
bool parse_number(std::string_view token, double& value) {
  const std::string owned(token);
  char* end = nullptr;
  value = std::strtod(owned.c_str(), &end);
  return !owned.empty() && end == owned.c_str() + owned.size();
}

// All of `token` as a decimal integer that fits an int.
bool parse_index(std::string_view token, long& value) {
  const std::string owned(token);
  char* end = nullptr;
  errno = 0;
  value = std::strtol(owned.c_str(), &end, 10);
  return !owned.empty() && end == owned.c_str() + owned.size() && errno == 0 && value >= INT_MIN &&
         value <= INT_MAX;
}

}  // namespace

Result<TriangleMesh> parse_obj_mesh(std::string_view text, std::string_view name) {
  const std::string file(name);
  const HeldFloatingPointExceptions held;
  TriangleMesh mesh;
  std::vector<int> triangle_line;  // per triangle, its face's line (for index errors)
  std::vector<long> corners;
  TextLines lines(text, file);
  while (auto next = lines.next()) {
    if (!*next) return fail(next->error().message);
    const std::string_view line = **next;
    const std::string& where = lines.where();
    std::string_view rest = line;
    const std::string_view keyword = next_token(rest);
    if (keyword == "v") {
      double xyz[3];
      for (double& c : xyz) {
        const std::string_view token = next_token(rest);
        if (!parse_number(token, c)) {
          return fail(where + ": expected a vertex 'v x y z' of three numbers, got " +
                      quote_input(line));
        }
      }
      for (std::string_view extra = next_token(rest); !extra.empty(); extra = next_token(rest)) {
        double ignored = 0.0;
        if (!parse_number(extra, ignored)) {
          return fail(where + ": expected a vertex 'v x y z' of three numbers, got " +
                      quote_input(line));
        }
      }
      if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2])) {
        return fail(where + ": the vertex is not finite, got " + quote_input(line));
      }
      mesh.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
    } else if (keyword == "f") {
      corners.clear();
      for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
        long index = 0;
        if (!parse_index(token.substr(0, token.find('/')), index)) {
          return fail(where +
                      ": expected face corners 'v', 'v/vt', 'v//vn' or 'v/vt/vn' with an "
                      "integer v, got " +
                      quote_input(line));
        }
        const long count = static_cast<long>(mesh.vertices.size());
        if (index == 0) {
          return fail(where + ": vertex index 0 (OBJ indices start at 1), got " +
                      quote_input(line));
        }
        if (index < 0 && count + index < 0) {
          return fail(where + ": vertex index " + std::to_string(index) + " reaches before the " +
                      "first vertex (" + std::to_string(count) + " read so far), got " +
                      quote_input(line));
        }
        // 0-based; a positive index may name a vertex further down, checked at the end.
        corners.push_back(index < 0 ? count + index : index - 1);
      }
      if (corners.size() < 3) {
        return fail(where + ": a face needs at least three vertices, got " + quote_input(line));
      }
      // Fan triangulation: exact for the convex polygons exporters write.
      for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
        mesh.triangles.push_back({static_cast<int>(corners[0]), static_cast<int>(corners[k]),
                                  static_cast<int>(corners[k + 1])});
        triangle_line.push_back(lines.number());
      }
    }
  }
  if (mesh.vertices.empty() && mesh.triangles.empty()) {
    return fail(file + ": no vertices and no faces (an empty OBJ file?)");
  }
  if (mesh.triangles.empty()) return fail(file + ": no faces (expected lines 'f a b c')");
  // What TriangleMesh::validate() would refuse, said with the face's line.
  const long count = static_cast<long>(mesh.vertices.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const std::string where = file + " line " + std::to_string(triangle_line[t]);
    for (int v : tri) {
      if (v >= count) {
        return fail(where + ": vertex index " + std::to_string(v + 1) + " is beyond the file's " +
                    std::to_string(count) + " vertices");
      }
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
      return fail(where + ": the face repeats a vertex");
    }
    const Vec3& a = mesh.vertices[tri[0]];
    if (!((mesh.vertices[tri[1]] - a).cross(mesh.vertices[tri[2]] - a).norm() > 0.0)) {
      return fail(where + ": the face has a triangle of zero area (vertices " +
                  std::to_string(tri[0] + 1) + ", " + std::to_string(tri[1] + 1) + ", " +
                  std::to_string(tri[2] + 1) + ")");
    }
  }
  if (auto error = mesh.validate()) {
    return fail(file + ": " + error->message);
  }
  return mesh;
}

Result<TriangleMesh> read_obj_mesh(const std::filesystem::path& path) {
  auto bytes = read_file_bytes(path, kMaxObjFileBytes);
  if (!bytes) return fail(bytes.error().message);
  return parse_obj_mesh(*bytes, shown_path(path.string()));
}

}  // namespace animkit
