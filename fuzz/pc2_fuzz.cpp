// Fuzzes the PC2 point cache parser (the cloth animation files animkit writes and reads back).
#include <cstddef>
#include <cstdint>
#include <span>

#include "animkit/io/point_cache.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using animkit::fuzz::check;
  const auto cache = animkit::parse_pc2(std::as_bytes(std::span(data, size)), "fuzz.pc2");
  if (!cache) {
    animkit::fuzz::check_message(cache.error().message, "fuzz.pc2");
    return 0;
  }
  check(cache->points >= 0, "a point count is not negative");
  // Every byte after the 32-byte header is a coordinate: nothing invented, nothing skipped.
  std::size_t coordinates = 0;
  for (const auto& frame : cache->frames) {
    check(frame.size() == 3 * static_cast<std::size_t>(cache->points), "frames hold every point");
    coordinates += frame.size();
  }
  check(32 + 4 * coordinates == size, "the frames are the file's bytes after the header");
  return 0;
}
