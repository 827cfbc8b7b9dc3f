// libFuzzer target: any bytes as an MNIST IDX image file. The first byte picks the index (so
// out-of-range and negative indices are tried too); the rest is the file.
#include <cstdint>
#include <cstdlib>
#include <span>

#include "animkit/io/image_decode.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const int index = static_cast<int>(static_cast<std::int8_t>(data[0]));
  const auto image = animkit::decode_mnist_image({data + 1, size - 1}, index, "fuzz");
  if (image && image->pixels.size() != static_cast<std::size_t>(image->width) * image->height) {
    std::abort();
  }
  return 0;
}
