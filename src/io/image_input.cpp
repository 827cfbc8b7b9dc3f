#include "animkit/io/image_input.h"

#include "animkit/io/image_decode.h"
#include "image_file.h"

namespace animkit {

Result<GrayImage> read_gray_image(const std::filesystem::path& path) {
  auto bytes = io_detail::read_file_bytes(path);
  if (!bytes) return fail(bytes.error().message);
  return decode_gray_image(*bytes, path.string());
}

Result<GrayImage> read_mnist_image(const std::filesystem::path& path, int index) {
  auto bytes = io_detail::read_file_bytes(path);
  if (!bytes) return fail(bytes.error().message);
  return decode_mnist_image(*bytes, index, path.string());
}

}  // namespace animkit
