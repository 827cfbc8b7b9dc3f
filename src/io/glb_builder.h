#pragma once
// Assembles a binary glTF 2.0 file (.glb): the JSON document and one binary buffer holding
// every accessor's data. Layout per the glTF 2.0 specification, section "GLB File Format
// Specification"
// (https://registry.khronos.org/glTF/specs/2.0/glTF-2.0.html#glb-file-format-specification): a
// 12-byte header, a JSON chunk padded with spaces and a BIN chunk padded with zeros, each to a
// multiple of 4 bytes.
#include <array>
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "animkit/core/result.h"
#include "animkit/core/types.h"

namespace animkit {

class GlbBuilder {
 public:
  /// glTF's bufferView targets: vertex attributes and triangle indices.
  static constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

  explicit GlbBuilder(std::string generator);

  /// The document, to add nodes, meshes, materials, animations and scenes to.
  nlohmann::ordered_json& document() { return document_; }

  /// An accessor of `values.size() / components` elements of `type` ("SCALAR", "VEC3",
  /// "VEC4") in a bufferView of its own; with `bounds`, its per-component min and max (which
  /// glTF requires of positions and animation inputs). `target` 0 for none.
  int add_floats(std::span<const float> values, const char* type, int components, bool bounds,
                 int target);
  /// Unsigned 16-bit vertex attributes (e.g. JOINTS_0, "VEC4") with the array-buffer target.
  int add_unsigned_shorts(std::span<const std::uint16_t> values, const char* type, int components);
  /// Triangle indices (unsigned 32-bit) as a SCALAR accessor with the element-array target.
  int add_indices(std::span<const std::uint32_t> indices);
  /// A SCALAR float accessor of `count` zeros except `values` at `indices` (glTF's sparse
  /// storage: no bufferView for the zeros, so a one-hot weight table costs one entry a row).
  int add_sparse_floats(std::size_t count, std::span<const std::uint32_t> indices,
                        std::span<const float> values);

  /// The whole .glb file; an error when it would pass the format's 4 GiB.
  Result<std::string> glb() const;

 private:
  int add_view(const void* data, std::size_t bytes, int target);
  int add_accessor(nlohmann::ordered_json accessor);

  nlohmann::ordered_json document_;
  std::vector<std::byte> binary_;
};

/// Unit vertex normals of a mesh (positions: x, y, z per vertex): the sum of the adjacent
/// triangles' area-weighted normals, +Y for a vertex on no triangle of non-zero area (glTF
/// requires unit NORMALs).
std::vector<float> gltf_vertex_normals(std::span<const float> positions,
                                       const std::vector<std::array<int, 3>>& triangles);
/// The triangles' vertex indices, three a triangle.
std::vector<std::uint32_t> gltf_indices(const std::vector<std::array<int, 3>>& triangles);
/// A plain material: base colour (linear RGBA), not metallic, rough.
nlohmann::ordered_json gltf_material(const char* name, std::array<double, 4> colour,
                                     bool double_sided);

}  // namespace animkit
