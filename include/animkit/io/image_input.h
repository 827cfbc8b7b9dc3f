#pragma once
// Reading the pictures a drawing can come from: PNG, JPEG, BMP (anything stb_image reads) and
// the MNIST handwritten-digit files (the IDX format of LeCun et al.).
#include <filesystem>

#include "animkit/core/image.h"
#include "animkit/core/result.h"

namespace animkit {

/// Reads an image as 8-bit gray (colour is averaged by stb_image's luma weights). Errors name
/// the file: missing, empty, not an image or truncated (with stb_image's reason), larger than
/// kMaxImageSide on a side (checked before decoding).
Result<GrayImage> read_gray_image(const std::filesystem::path& path);

/// Image `index` of an MNIST IDX image file (magic 0x00000803: unsigned bytes, 3 dimensions:
/// count x rows x columns, big-endian sizes; digits are white on black). Errors: a missing or
/// truncated file, a wrong magic number, an index out of range, absurd sizes.
Result<GrayImage> read_mnist_image(const std::filesystem::path& path, int index);

}  // namespace animkit
