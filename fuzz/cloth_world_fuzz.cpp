// Fuzzes building a world from a scene file: the parsed scene, if small, through
// build_cloth_world (the cloth, colliders, the start checks of contact: inside, touching,
// crossing). Any bytes give either a world or one clean error line; nothing is stepped.
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <variant>

#include "animkit/cloth/cloth_world.h"
#include "animkit/collision/collider_surface.h"
#include "animkit/core/utf8.h"
#include "animkit/io/cloth_scene_file.h"
#include "fuzz_check.h"

namespace {

// Scenes this small build in milliseconds; larger ones would only make the fuzzer slower.
bool small(const animkit::ClothWorldDesc& world) {
  const auto* grid = std::get_if<animkit::GridClothOptions>(&world.cloth);
  if (!grid || grid->cells > 12 || world.colliders.size() > 4) return false;
  for (const animkit::ColliderDesc& c : world.colliders)
    if (animkit::surface_triangle_count(c.shape, c.tessellation) > 5000) return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using animkit::fuzz::check;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto scene = animkit::parse_cloth_scene(text, "fuzz.json", "/nonexistent-animkit-fuzz");
  if (!scene || !small(*scene)) return 0;
  const auto world = animkit::build_cloth_world(*scene);
  if (!world) {
    const std::string& message = world.error().message;
    check(!message.empty() && message.size() < 800, "an error message is 1..799 bytes");
    check(message.find_first_of("\n\r\x1b") == std::string::npos,
          "an error message has no newline or escape");
    check(animkit::decode_utf8(message).has_value(), "an error message is UTF-8");
  }
  return 0;
}
