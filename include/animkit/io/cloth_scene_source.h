#pragma once
// Where a cloth scene comes from, as the user names it (`--scene NAME|FILE.json`): a built-in
// scene of the registry (scene/cloth_scenes.h) or a JSON scene file (io/cloth_scene_file.h).
#include <string_view>

#include "animkit/cloth/cloth_world.h"
#include "animkit/core/result.h"

namespace animkit {

/// The built-in scene called `name_or_file`, else, when it ends in ".json", that file read
/// (read_cloth_scene's errors). Anything else: "unknown scene 'x' (expected a .json file or
/// one of: lab, drape-sphere, ...)".
Result<ClothWorldDesc> open_cloth_scene(std::string_view name_or_file);

}  // namespace animkit
