#include "animkit/io/image_input.h"

#include <stb_image.h>

#include <cstdio>
#include <fstream>
#include <memory>
#include <string>

#include "animkit/trajectory/image_strokes.h"

namespace animkit {

namespace {

std::string name(const std::filesystem::path& path) {
  return path.string();
}

// The file's size, or an error naming why it cannot be read.
Result<std::uintmax_t> readable_size(const std::filesystem::path& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status)) return fail(name(path) + ": no such file");
  if (std::filesystem::is_directory(status)) return fail(name(path) + ": is a folder, not a file");
  const auto size = std::filesystem::file_size(path, error);
  if (error) return fail(name(path) + ": " + error.message());
  if (size == 0) return fail(name(path) + ": the file is empty");
  return size;
}

std::uint32_t big_endian(const unsigned char* b) {
  return (std::uint32_t{b[0]} << 24) | (std::uint32_t{b[1]} << 16) | (std::uint32_t{b[2]} << 8) |
         std::uint32_t{b[3]};
}

}  // namespace

Result<GrayImage> read_gray_image(const std::filesystem::path& path) {
  if (auto size = readable_size(path); !size) return fail(size.error().message);
  int width = 0, height = 0, channels = 0;
  if (!stbi_info(path.c_str(), &width, &height, &channels)) {
    const char* reason = stbi_failure_reason();
    return fail(name(path) + ": not an image stb_image can read (" +
                (reason ? reason : "unknown format") + ")");
  }
  if (width > kMaxImageSide || height > kMaxImageSide) {
    return fail(name(path) + ": the image is " + std::to_string(width) + "x" +
                std::to_string(height) + " pixels, larger than the limit of " +
                std::to_string(kMaxImageSide) + "x" + std::to_string(kMaxImageSide));
  }
  // Gray and alpha, so a drawing on a transparent background reads as ink on white paper
  // (stb would otherwise drop the alpha and see transparent black everywhere).
  std::unique_ptr<stbi_uc, void (*)(void*)> data(
      stbi_load(path.c_str(), &width, &height, &channels, 2), stbi_image_free);
  if (!data) {
    const char* reason = stbi_failure_reason();
    return fail(name(path) + ": cannot decode the image (" + (reason ? reason : "unknown reason") +
                ")");
  }
  GrayImage image(width, height);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const int gray = data.get()[2 * i], alpha = data.get()[2 * i + 1];
    // Composited over white: g' = 255 - a (255 - g) / 255, rounded.
    image.pixels[i] = static_cast<std::uint8_t>(255 - (alpha * (255 - gray) + 127) / 255);
  }
  return image;
}

Result<GrayImage> read_mnist_image(const std::filesystem::path& path, int index) {
  const auto size = readable_size(path);
  if (!size) return fail(size.error().message);
  std::ifstream in(path, std::ios::binary);
  unsigned char header[16];
  if (!in.read(reinterpret_cast<char*>(header), sizeof header)) {
    return fail(name(path) + ": too short for an MNIST IDX header (16 bytes)");
  }
  const std::uint32_t magic = big_endian(header);
  if (magic != 0x00000803u) {
    char found[16];
    std::snprintf(found, sizeof found, "0x%08x", magic);
    return fail(name(path) + ": not an MNIST image file (magic number " + found +
                ", expected 0x00000803)");
  }
  const std::uint32_t count = big_endian(header + 4), rows = big_endian(header + 8),
                      columns = big_endian(header + 12);
  if (rows == 0 || columns == 0 || rows > kMaxImageSide || columns > kMaxImageSide) {
    return fail(name(path) + ": absurd image size " + std::to_string(rows) + "x" +
                std::to_string(columns));
  }
  if (index < 0 || static_cast<std::uint32_t>(index) >= count) {
    return fail(name(path) + ": image index " + std::to_string(index) +
                " is out of range (the file has " + std::to_string(count) + " images)");
  }
  const std::uintmax_t image_bytes = std::uintmax_t{rows} * columns;
  const std::uintmax_t needed = 16 + image_bytes * (static_cast<std::uintmax_t>(index) + 1);
  if (*size < needed) {
    return fail(name(path) + ": truncated (" + std::to_string(*size) + " bytes, image " +
                std::to_string(index) + " needs " + std::to_string(needed) + ")");
  }
  GrayImage image(static_cast<int>(columns), static_cast<int>(rows));
  in.seekg(static_cast<std::streamoff>(16 + image_bytes * static_cast<std::uintmax_t>(index)));
  if (!in.read(reinterpret_cast<char*>(image.pixels.data()),
               static_cast<std::streamsize>(image_bytes))) {
    return fail(name(path) + ": cannot read image " + std::to_string(index));
  }
  return image;
}

}  // namespace animkit
