#pragma once
// Decoding JPEG through libjpeg-turbo (the libjpeg API): baseline and progressive, gray, YCbCr,
// CMYK, into 8-bit RGBA (alpha as stored). Internal: callers go through animkit/io/image_decode.h,
// which picks the decoder from the file's first bytes.
#include <cstdint>
#include <span>
#include <string_view>

#include "animkit/core/image.h"
#include "animkit/core/result.h"

namespace animkit::image_detail {

/// `bytes` is the whole file; `name` starts every error message. Refuses, before allocating
/// pixels, a size above kMaxImageSide and data shorter than the header announces.
Result<Image> decode_jpeg(std::span<const std::uint8_t> bytes, std::string_view name);

}  // namespace animkit::image_detail
