#include "animkit/io/image_decode.h"

#include <cstdio>
#include <cstring>
#include <string>

#include "animkit/trajectory/image_strokes.h"
#include "bmp_decode.h"
#include "jpeg_decode.h"
#include "png_decode.h"
#include "pnm_decode.h"

namespace animkit {

namespace {

bool starts_with(std::span<const std::uint8_t> bytes, std::string_view magic) {
  return bytes.size() >= magic.size() && std::memcmp(bytes.data(), magic.data(), magic.size()) == 0;
}

// Formats people may try that we recognise but do not read, named in the refusal.
const char* known_unsupported(std::span<const std::uint8_t> bytes) {
  if (starts_with(bytes, "GIF87a") || starts_with(bytes, "GIF89a")) return "GIF";
  if (starts_with(bytes, "II*") || starts_with(bytes, std::string_view("MM\0*", 4))) return "TIFF";
  if (starts_with(bytes, "RIFF") && bytes.size() >= 12 &&
      std::memcmp(bytes.data() + 8, "WEBP", 4) == 0) {
    return "WebP";
  }
  if (starts_with(bytes, "8BPS")) return "Photoshop";
  if (starts_with(bytes, "P7")) return "PAM";
  return nullptr;
}

std::uint32_t big_endian(const std::uint8_t* b) {
  return (std::uint32_t{b[0]} << 24) | (std::uint32_t{b[1]} << 16) | (std::uint32_t{b[2]} << 8) |
         std::uint32_t{b[3]};
}

}  // namespace

Result<Image> decode_rgba_image(std::span<const std::uint8_t> bytes, std::string_view name) {
  if (bytes.empty()) return fail(std::string(name) + ": the file is empty");
  if (starts_with(bytes, "\x89PNG\r\n\x1a\n")) return image_detail::decode_png(bytes, name);
  if (starts_with(bytes, "\xff\xd8\xff")) return image_detail::decode_jpeg(bytes, name);
  if (starts_with(bytes, "BM")) return image_detail::decode_bmp(bytes, name);
  if (bytes.size() >= 2 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '6') {
    return image_detail::decode_pnm(bytes, name);
  }
  if (const char* format = known_unsupported(bytes)) {
    return fail(std::string(name) + ": " + format + " images are not supported (supported: " +
                std::string(kSupportedImageFormats) + ")");
  }
  return fail(std::string(name) + ": not an image format animkit reads (supported: " +
              std::string(kSupportedImageFormats) + ")");
}

Result<GrayImage> decode_gray_image(std::span<const std::uint8_t> bytes, std::string_view name) {
  auto rgba = decode_rgba_image(bytes, name);
  if (!rgba) return fail(rgba.error().message);
  GrayImage gray(rgba->width, rgba->height);
  for (std::size_t i = 0; i < gray.pixels.size(); ++i) {
    const Pixel& p = rgba->pixels[i];
    // Luma in 1/256ths (the weights stb_image used, so pictures threshold as before); exact
    // for gray pixels since the weights sum to 256.
    const int luma = (77 * p.r + 150 * p.g + 29 * p.b) >> 8;
    // Composited over white: g' = 255 - a (255 - g) / 255, rounded.
    gray.pixels[i] = static_cast<std::uint8_t>(255 - (p.a * (255 - luma) + 127) / 255);
  }
  return gray;
}

Result<GrayImage> decode_mnist_image(std::span<const std::uint8_t> bytes, int index,
                                     std::string_view name) {
  const std::string file(name);
  if (bytes.size() < 16) return fail(file + ": too short for an MNIST IDX header (16 bytes)");
  const std::uint32_t magic = big_endian(bytes.data());
  if (magic != 0x00000803u) {
    char found[16];
    std::snprintf(found, sizeof found, "0x%08x", magic);
    return fail(file + ": not an MNIST image file (magic number " + found +
                ", expected 0x00000803)");
  }
  const std::uint32_t count = big_endian(bytes.data() + 4), rows = big_endian(bytes.data() + 8),
                      columns = big_endian(bytes.data() + 12);
  if (rows == 0 || columns == 0 || rows > kMaxImageSide || columns > kMaxImageSide) {
    return fail(file + ": absurd image size " + std::to_string(rows) + "x" +
                std::to_string(columns));
  }
  if (index < 0 || static_cast<std::uint32_t>(index) >= count) {
    return fail(file + ": image index " + std::to_string(index) +
                " is out of range (the file has " + std::to_string(count) + " images)");
  }
  const std::uint64_t image_bytes = std::uint64_t{rows} * columns;
  const std::uint64_t start = 16 + image_bytes * static_cast<std::uint64_t>(index);
  if (bytes.size() < start + image_bytes) {
    return fail(file + ": truncated (" + std::to_string(bytes.size()) + " bytes, image " +
                std::to_string(index) + " needs " + std::to_string(start + image_bytes) + ")");
  }
  GrayImage image(static_cast<int>(columns), static_cast<int>(rows));
  std::memcpy(image.pixels.data(), bytes.data() + start, image_bytes);
  return image;
}

}  // namespace animkit
