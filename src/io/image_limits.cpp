#include "image_limits.h"

#include "animkit/trajectory/image_strokes.h"

namespace animkit::image_detail {

Result<void> check_image_side(std::uint64_t width, std::uint64_t height, std::string_view name) {
  if (width <= kMaxImageSide && height <= kMaxImageSide) return {};
  return fail(std::string(name) + ": the image is " + std::to_string(width) + "x" +
              std::to_string(height) + " pixels, larger than the limit of " +
              std::to_string(kMaxImageSide) + "x" + std::to_string(kMaxImageSide));
}

std::unexpected<Error> truncated(std::string_view name, std::string_view format,
                                 std::string_view detail) {
  return fail(std::string(name) + ": truncated " + std::string(format) + " (" +
              std::string(detail) + ")");
}

std::unexpected<Error> corrupt(std::string_view name, std::string_view format,
                               std::string_view detail) {
  return fail(std::string(name) + ": corrupt " + std::string(format) + " (" + std::string(detail) +
              ")");
}

}  // namespace animkit::image_detail
