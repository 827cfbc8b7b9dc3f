#pragma once
// Decoding pictures held in memory: PNG (libpng), JPEG (libjpeg-turbo), BMP and PNM (our own
// strict readers), and MNIST IDX digit files. The file readers (image_input.h, png.h) read the
// bytes and call these; fuzzers call them directly.
//
// Every decoder is strict: a file that ends before the data its header announces is an error
// ("truncated"), never a picture with the rest filled in, and so is damaged data ("corrupt").
// Sizes above kMaxImageSide are refused from the header, before pixels are allocated.
#include <cstdint>
#include <span>
#include <string_view>

#include "animkit/core/image.h"
#include "animkit/core/result.h"

namespace animkit {

/// The formats decode_rgba_image reads, as error messages list them.
inline constexpr std::string_view kSupportedImageFormats = "PNG, JPEG, BMP, PNM/PGM/PPM/PBM";

/// Decodes a whole image file held in `bytes` as 8-bit RGBA, alpha as stored (16-bit samples
/// rounded to 8 bits). The format comes from the first bytes, not the name. `name` (usually
/// the path) starts every error message: "NAME: truncated PNG (...)", "NAME: corrupt JPEG
/// (libjpeg: ...)", "NAME: the image is WxH pixels, larger than the limit of 4096x4096",
/// "NAME: not an image format animkit reads (supported: ...)".
Result<Image> decode_rgba_image(std::span<const std::uint8_t> bytes, std::string_view name);

/// decode_rgba_image, then 8-bit gray: luma (0.30 R + 0.59 G + 0.11 B, in 1/256ths) composited
/// over white, so a drawing on a transparent background reads as ink on white paper.
Result<GrayImage> decode_gray_image(std::span<const std::uint8_t> bytes, std::string_view name);

/// Image `index` of an MNIST IDX image file held in `bytes` (magic 0x00000803: unsigned bytes,
/// 3 dimensions: count x rows x columns, big-endian sizes; digits are white on black). Errors:
/// too short for the header, a wrong magic number, absurd sizes, an index out of range, a
/// file that ends before the image.
Result<GrayImage> decode_mnist_image(std::span<const std::uint8_t> bytes, int index,
                                     std::string_view name);

}  // namespace animkit
