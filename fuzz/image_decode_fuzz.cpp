// libFuzzer target: any bytes through the image decoders (PNG, JPEG, BMP, PNM), as RGBA and
// as gray. A decode either fails with a message naming the input or returns a picture whose
// size matches its pixels and stays within kMaxImageSide.
#include <cstdint>
#include <cstdlib>
#include <span>

#include "animkit/io/image_decode.h"
#include "animkit/trajectory/image_strokes.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  const auto rgba = animkit::decode_rgba_image(bytes, "fuzz");
  if (rgba) {
    if (rgba->width <= 0 || rgba->height <= 0 || rgba->width > animkit::kMaxImageSide ||
        rgba->height > animkit::kMaxImageSide ||
        rgba->pixels.size() != static_cast<std::size_t>(rgba->width) * rgba->height) {
      std::abort();
    }
  } else if (rgba.error().message.rfind("fuzz: ", 0) != 0) {
    std::abort();  // every message names its input
  }
  const auto gray = animkit::decode_gray_image(bytes, "fuzz");
  if (gray.has_value() != rgba.has_value()) std::abort();
  if (gray && gray->pixels.size() != rgba->pixels.size()) std::abort();
  return 0;
}
