#include "animkit/io/cloth_scene_source.h"

#include <filesystem>
#include <string>

#include "animkit/core/quote.h"
#include "animkit/io/cloth_scene_file.h"
#include "animkit/scene/cloth_scenes.h"

namespace animkit {

Result<ClothWorldDesc> open_cloth_scene(std::string_view name_or_file) {
  if (const ClothSceneEntry* entry = find_cloth_scene(name_or_file)) return entry->make();
  if (name_or_file.ends_with(".json"))
    return read_cloth_scene(std::filesystem::path(std::string(name_or_file)));
  return fail("unknown scene " + quote_input(name_or_file) +
              " (expected a .json file or one of: " + cloth_scene_names() + ")");
}

}  // namespace animkit
