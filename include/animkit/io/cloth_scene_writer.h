#pragma once
// A scene as a scene file (the format cloth_scene_file.h reads): a built-in scene written out
// to start one's own from. Everything the format holds is written, defaults included, so the
// file shows every knob; reading it back gives the same scene.
#include <string>

#include "animkit/cloth/cloth_world.h"
#include "animkit/core/result.h"

namespace animkit {

/// The scene as scene-file JSON. The integrator is written as its registry name with its
/// tolerance (and Newton's velocity tolerance), which is what the format holds. Errors: a
/// cloth or collider from a triangle mesh (the format takes those from OBJ files, which this
/// does not write).
Result<std::string> cloth_scene_json(const ClothWorldDesc& scene);

}  // namespace animkit
