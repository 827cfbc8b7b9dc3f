#include "glb_builder.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace animkit {

namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67;                           // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;                          // "JSON"
constexpr std::uint32_t kBinaryChunk = 0x004E4942;                        // "BIN\0"
constexpr int kFloat = 5126, kUnsignedInt = 5125, kUnsignedShort = 5123;  // accessor componentType

void append_u32(std::string& out, std::uint32_t value) {
  // glTF is little-endian, as is every machine animkit builds on (x86-64, AArch64).
  char bytes[4];
  std::memcpy(bytes, &value, 4);
  out.append(bytes, 4);
}

std::size_t padded(std::size_t size) {
  return (size + 3) / 4 * 4;
}

}  // namespace

GlbBuilder::GlbBuilder(std::string generator) {
  document_["asset"] = {{"version", "2.0"}, {"generator", std::move(generator)}};
  document_["buffers"] = nlohmann::ordered_json::array();
  document_["bufferViews"] = nlohmann::ordered_json::array();
  document_["accessors"] = nlohmann::ordered_json::array();
}

int GlbBuilder::add_view(const void* data, std::size_t bytes, int target) {
  binary_.resize(padded(binary_.size()));  // every view starts 4-byte aligned
  const std::size_t offset = binary_.size();
  binary_.resize(offset + bytes);
  if (bytes > 0) std::memcpy(binary_.data() + offset, data, bytes);
  nlohmann::ordered_json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}};
  if (target != 0) view["target"] = target;
  document_["bufferViews"].push_back(std::move(view));
  return static_cast<int>(document_["bufferViews"].size()) - 1;
}

int GlbBuilder::add_accessor(nlohmann::ordered_json accessor) {
  document_["accessors"].push_back(std::move(accessor));
  return static_cast<int>(document_["accessors"].size()) - 1;
}

int GlbBuilder::add_floats(std::span<const float> values, const char* type, int components,
                           bool bounds, int target) {
  const std::size_t count = values.size() / static_cast<std::size_t>(components);
  nlohmann::ordered_json accessor = {
      {"bufferView", add_view(values.data(), values.size_bytes(), target)},
      {"componentType", kFloat},
      {"count", count},
      {"type", type}};
  if (bounds) {
    std::vector<float> low(components, std::numeric_limits<float>::max());
    std::vector<float> high(components, std::numeric_limits<float>::lowest());
    for (std::size_t i = 0; i < values.size(); ++i) {
      const std::size_t c = i % static_cast<std::size_t>(components);
      low[c] = std::min(low[c], values[i]);
      high[c] = std::max(high[c], values[i]);
    }
    accessor["min"] = low;
    accessor["max"] = high;
  }
  return add_accessor(std::move(accessor));
}

int GlbBuilder::add_unsigned_shorts(std::span<const std::uint16_t> values, const char* type,
                                    int components) {
  return add_accessor({{"bufferView", add_view(values.data(), values.size_bytes(), kArrayBuffer)},
                       {"componentType", kUnsignedShort},
                       {"count", values.size() / static_cast<std::size_t>(components)},
                       {"type", type}});
}

int GlbBuilder::add_indices(std::span<const std::uint32_t> indices) {
  return add_accessor(
      {{"bufferView", add_view(indices.data(), indices.size_bytes(), kElementArrayBuffer)},
       {"componentType", kUnsignedInt},
       {"count", indices.size()},
       {"type", "SCALAR"}});
}

int GlbBuilder::add_sparse_floats(std::size_t count, std::span<const std::uint32_t> indices,
                                  std::span<const float> values) {
  const int index_view = add_view(indices.data(), indices.size_bytes(), 0);
  const int value_view = add_view(values.data(), values.size_bytes(), 0);
  return add_accessor({{"componentType", kFloat},
                       {"count", count},
                       {"type", "SCALAR"},
                       {"sparse",
                        {{"count", indices.size()},
                         {"indices", {{"bufferView", index_view}, {"componentType", kUnsignedInt}}},
                         {"values", {{"bufferView", value_view}}}}}});
}

Result<std::string> GlbBuilder::glb() const {
  nlohmann::ordered_json document = document_;
  const std::size_t binary_size = padded(binary_.size());
  if (binary_size > 0) {
    document["buffers"] = nlohmann::ordered_json::array({{{"byteLength", binary_size}}});
  } else {
    document.erase("buffers");
  }
  std::string json = document.dump();
  json.resize(padded(json.size()), ' ');
  const std::size_t total = 12 + 8 + json.size() + (binary_size > 0 ? 8 + binary_size : 0);
  if (total > std::numeric_limits<std::uint32_t>::max()) {
    return fail("the glTF file would be " + std::to_string(total) +
                " bytes; a .glb holds at most 4 GiB (4294967295 bytes)");
  }
  std::string out;
  out.reserve(total);
  append_u32(out, kGlbMagic);
  append_u32(out, 2);
  append_u32(out, static_cast<std::uint32_t>(total));
  append_u32(out, static_cast<std::uint32_t>(json.size()));
  append_u32(out, kJsonChunk);
  out += json;
  if (binary_size > 0) {
    append_u32(out, static_cast<std::uint32_t>(binary_size));
    append_u32(out, kBinaryChunk);
    out.append(reinterpret_cast<const char*>(binary_.data()), binary_.size());
    out.append(binary_size - binary_.size(), '\0');
  }
  return out;
}

std::vector<float> gltf_vertex_normals(std::span<const float> positions,
                                       const std::vector<std::array<int, 3>>& triangles) {
  std::vector<Vec3> sums(positions.size() / 3, Vec3::Zero());
  const auto at = [&](int v) {
    return Vec3(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
  };
  for (const auto& t : triangles) {
    const Vec3 n = (at(t[1]) - at(t[0])).cross(at(t[2]) - at(t[0]));
    for (int v : t) sums[v] += n;
  }
  std::vector<float> normals;
  normals.reserve(positions.size());
  for (const Vec3& sum : sums) {
    const double length = sum.norm();
    const Vec3 n = length > 0.0 && std::isfinite(length) ? Vec3(sum / length) : Vec3::UnitY();
    for (int c = 0; c < 3; ++c) normals.push_back(static_cast<float>(n[c]));
  }
  return normals;
}

std::vector<std::uint32_t> gltf_indices(const std::vector<std::array<int, 3>>& triangles) {
  std::vector<std::uint32_t> indices;
  indices.reserve(3 * triangles.size());
  for (const auto& t : triangles)
    for (int v : t) indices.push_back(static_cast<std::uint32_t>(v));
  return indices;
}

nlohmann::ordered_json gltf_material(const char* name, std::array<double, 4> colour,
                                     bool double_sided) {
  return {{"name", name},
          {"pbrMetallicRoughness",
           {{"baseColorFactor", colour}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.8}}},
          {"doubleSided", double_sided}};
}

}  // namespace animkit
