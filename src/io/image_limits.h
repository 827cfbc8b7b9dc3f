#pragma once
// Shared by the image decoders: the size limit, checked from a header before anything is
// allocated, and the wording of the errors every format uses.
#include <cstdint>
#include <string>
#include <string_view>

#include "animkit/core/result.h"

namespace animkit::image_detail {

/// Refuses a declared size larger than kMaxImageSide on a side, with the message every
/// format shares ("NAME: the image is WxH pixels, larger than the limit of 4096x4096").
Result<void> check_image_side(std::uint64_t width, std::uint64_t height, std::string_view name);

/// "NAME: truncated FORMAT (detail)": the file ends before the data its header announces.
std::unexpected<Error> truncated(std::string_view name, std::string_view format,
                                 std::string_view detail);

/// "NAME: corrupt FORMAT (detail)": the data is there but cannot be what the format says.
std::unexpected<Error> corrupt(std::string_view name, std::string_view format,
                               std::string_view detail);

}  // namespace animkit::image_detail
