// Fuzzes the JSON cloth scene reader (`animkit cloth --scene FILE.json`): any bytes give either
// a valid world description or one clean error line naming the file.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "animkit/io/cloth_scene_file.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using animkit::fuzz::check;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // OBJ files a scene names are looked up in a folder that does not exist: an error, no I/O.
  const auto scene = animkit::parse_cloth_scene(text, "fuzz.json", "/nonexistent-animkit-fuzz");
  if (!scene) {
    animkit::fuzz::check_message(scene.error().message, "fuzz.json");
    return 0;
  }
  check(!scene->validate().has_value(), "a parsed scene is valid");
  return 0;
}
