#include "animkit/io/png.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <memory>
#include <string_view>

#include "animkit/io/atomic_write.h"

namespace animkit {

namespace {
void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<unsigned char>*>(context);
  const auto* bytes = static_cast<const unsigned char*>(data);
  out->insert(out->end(), bytes, bytes + size);
}
}  // namespace

Result<std::vector<unsigned char>> encode_png(const Image& image) {
  if (image.empty() || image.width <= 0 || image.height <= 0) {
    return fail("cannot encode an empty image as PNG");
  }
  if (image.pixels.size() != static_cast<std::size_t>(image.width) * image.height) {
    return fail("image of " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                " has " + std::to_string(image.pixels.size()) + " pixels");
  }
  static_assert(sizeof(Pixel) == 4, "Pixel must be 4 packed bytes for the encoder");
  std::vector<unsigned char> bytes;
  if (!stbi_write_png_to_func(append_bytes, &bytes, image.width, image.height, 4,
                              image.pixels.data(), image.width * 4)) {
    return fail("the PNG encoder failed on a " + std::to_string(image.width) + "x" +
                std::to_string(image.height) + " image");
  }
  return bytes;
}

Result<void> write_png(const std::filesystem::path& path, const Image& image) {
  auto bytes = encode_png(image);
  if (!bytes) return fail(path.string() + ": " + bytes.error().message);
  return write_file_atomic(
      path, std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()));
}

Result<Image> read_image(const std::filesystem::path& path) {
  int width = 0, height = 0, channels = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> data(
      stbi_load(path.c_str(), &width, &height, &channels, 4), stbi_image_free);
  if (!data) {
    const char* reason = stbi_failure_reason();
    return fail(path.string() + ": cannot read the image (" +
                (reason ? std::string(reason) : std::string("unknown reason")) + ")");
  }
  Image image(width, height);
  std::copy_n(data.get(), static_cast<std::size_t>(width) * height * 4,
              reinterpret_cast<unsigned char*>(image.pixels.data()));
  return image;
}

}  // namespace animkit
