// Fuzzes the OBJ reader (`animkit cloth --mesh`, a scene's mesh cloth and mesh colliders): any
// bytes give either a valid triangle mesh or one clean error line naming the file.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "animkit/io/obj_mesh.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using animkit::fuzz::check;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto mesh = animkit::parse_obj_mesh(text, "fuzz.obj");
  if (!mesh) {
    animkit::fuzz::check_message(mesh.error().message, "fuzz.obj");
    return 0;
  }
  check(!mesh->validate().has_value(), "a parsed mesh is valid");
  return 0;
}
