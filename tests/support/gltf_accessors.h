#pragma once
// Reading glTF files back with tinygltf (Debian's libtinygltf-dev), a reader independent of
// animkit's writer: an accessor's floats, sparse storage applied (glTF 2.0 section 3.6.2.3,
// "Sparse Accessors"), which tinygltf parses but leaves to its caller.
#include <tiny_gltf.h>

#include <cstring>
#include <string>
#include <vector>

namespace animkit::testing {

inline tinygltf::Model load_glb(const std::string& bytes) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error, warning;
  const bool ok = loader.LoadBinaryFromMemory(&model, &error, &warning,
                                              reinterpret_cast<const unsigned char*>(bytes.data()),
                                              static_cast<unsigned int>(bytes.size()));
  if (!ok || !error.empty()) throw std::runtime_error("tinygltf: " + error);
  return model;
}

inline int component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    case TINYGLTF_TYPE_MAT4:
      return 16;
    default:
      throw std::runtime_error("unexpected accessor type");
  }
}

// Elements of `view` starting `offset` bytes in, as `T` (tightly packed, as animkit writes).
template <typename T>
std::vector<T> view_values(const tinygltf::Model& model, int view_index, std::size_t offset,
                           std::size_t count) {
  const tinygltf::BufferView& view = model.bufferViews.at(view_index);
  const tinygltf::Buffer& buffer = model.buffers.at(view.buffer);
  const std::size_t begin = view.byteOffset + offset;
  if (begin + count * sizeof(T) > view.byteOffset + view.byteLength)
    throw std::runtime_error("accessor runs past its bufferView");
  std::vector<T> values(count);
  std::memcpy(values.data(), buffer.data.data() + begin, count * sizeof(T));
  return values;
}

/// A float accessor's values, count x components, with its sparse entries applied.
inline std::vector<float> accessor_floats(const tinygltf::Model& model, int index) {
  const tinygltf::Accessor& a = model.accessors.at(index);
  if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) throw std::runtime_error("not floats");
  const std::size_t n = a.count * component_count(a.type);
  std::vector<float> values(n, 0.0f);
  if (a.bufferView >= 0) values = view_values<float>(model, a.bufferView, a.byteOffset, n);
  if (a.sparse.isSparse) {
    const std::size_t k = a.sparse.count, c = component_count(a.type);
    if (a.sparse.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
      throw std::runtime_error("sparse indices not unsigned int");
    const auto at = view_values<std::uint32_t>(model, a.sparse.indices.bufferView,
                                               a.sparse.indices.byteOffset, k);
    const auto put =
        view_values<float>(model, a.sparse.values.bufferView, a.sparse.values.byteOffset, k * c);
    for (std::size_t i = 0; i < k; ++i)
      for (std::size_t j = 0; j < c; ++j) values.at(at[i] * c + j) = put[i * c + j];
  }
  return values;
}

}  // namespace animkit::testing
