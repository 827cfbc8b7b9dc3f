#pragma once
// Reading the pictures a drawing can come from: PNG, JPEG, BMP, PNM (PGM, PPM, PBM) and the
// MNIST handwritten-digit files (the IDX format of LeCun et al.). The decoding itself is in
// image_decode.h.
#include <filesystem>

#include "animkit/core/image.h"
#include "animkit/core/result.h"

namespace animkit {

/// Reads an image as 8-bit gray (see decode_gray_image). Errors name the file: missing, a
/// folder, empty, not a supported format, truncated or corrupt (with the reason), larger than
/// kMaxImageSide on a side (checked from the header, before decoding).
Result<GrayImage> read_gray_image(const std::filesystem::path& path);

/// Image `index` of an MNIST IDX image file (magic 0x00000803: unsigned bytes, 3 dimensions:
/// count x rows x columns, big-endian sizes; digits are white on black). Errors: a missing or
/// truncated file, a wrong magic number, an index out of range, absurd sizes.
Result<GrayImage> read_mnist_image(const std::filesystem::path& path, int index);

}  // namespace animkit
