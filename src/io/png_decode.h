#pragma once
// Decoding PNG through libpng: every colour type and bit depth, interlaced or not, into 8-bit RGBA
// (alpha as stored). Internal: callers go through animkit/io/image_decode.h, which picks the
// decoder from the file's first bytes.
#include <cstdint>
#include <span>
#include <string_view>

#include "animkit/core/image.h"
#include "animkit/core/result.h"

namespace animkit::image_detail {

/// `bytes` is the whole file; `name` starts every error message. Refuses, before allocating
/// pixels, a size above kMaxImageSide and data shorter than the header announces.
Result<Image> decode_png(std::span<const std::uint8_t> bytes, std::string_view name);

}  // namespace animkit::image_detail
