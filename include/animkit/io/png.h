#pragma once
// PNG files written through libpng; pictures read back through image_decode.h.
#include <filesystem>

#include "animkit/core/image.h"
#include "animkit/core/result.h"

namespace animkit {

/// Encodes `image` as PNG and writes it whole or not at all (temporary file, then rename).
/// Errors: an empty image, an encoder failure, the file system's.
Result<void> write_png(const std::filesystem::path& path, const Image& image);

/// Encodes `image` as PNG bytes in memory.
Result<std::vector<unsigned char>> encode_png(const Image& image);

/// Reads a PNG (or any format decode_rgba_image reads) as RGBA. Errors name the file and the
/// reason (see decode_rgba_image, and read_gray_image for the file's own).
Result<Image> read_image(const std::filesystem::path& path);

}  // namespace animkit
