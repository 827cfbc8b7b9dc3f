#pragma once
// Cloth scenes as JSON files (`animkit cloth --scene FILE.json`, the viewer's scene menu): a
// ClothWorldDesc (cloth/cloth_world.h) written out. Every key is optional and defaults as the
// structs do (the lab's cloth, no colliders, 1/60 s, 300 frames); an unknown key is an error
// (a typo must not be silently ignored). Lengths in m, times in s, angles in degrees:
//
// {
//   "cloth": {"grid": 40, "size": 1.0, "height": 1.0, "pins": "corners" | "edge" | "none",
//             "rotation": {"axis": [1, 0, 0], "degrees": 90}, "offset": [x, y, z],
//             "material": "cotton" | {"density", "stretch", "shear", "bending", "damping"},
//             "mass", "stiffness", "damping",   (the lab's parameters, without a material)
//             "gravity": 9.81,                  (default 9.81 with a material, else 0.3)
//             or, instead of "grid": "mesh": "sheet.obj", "pin": [0, 7], "pin_box":
//             [[x0, y0, z0, x1, y1, z1]], "warp": [1, 0, 0]},
//   "colliders": [{"name": "ball", "shape": "sphere" | "box" | "capsule" | "mesh",
//                  "radius", "half_extents": [x, y, z], "half_length", "mesh": "body.obj",
//                  "position": [x, y, z], "rotation": {"axis", "degrees"},
//                  "velocity": [x, y, z], "angular_velocity": [x, y, z]  (rad/s, world axes),
//                  or "keyframes": [{"time", "position", "rotation"}],
//                  "friction": 0.3, "tessellation": 3}],
//   "ground": {"height": 0, "friction": 0.3},
//   "contact": {"thickness": 0.002, "stiffness": 0, "self_contact": true,
//               "self_friction": 0.3, "friction_passes": 1,
//               "hessian": "projected" | "gauss_newton" | "adaptive"},
//   "wind": {"velocity": [x, y, z], "gust": [x, y, z], "gust_frequency": 0.5,
//            "air_density": 1.2, "normal_drag": 1.2, "tangential_drag": 0.02},
//   "solver": {"integrator": "implicit-pcg", "tolerance": 1e-6, "substeps": 0,
//              "velocity_tolerance": 0, "linear_forcing": 0,   (these three: Newton's only)
//              "projection": "when_indefinite" | "always" | "with_terms"},
//   "dt": 0.0166667, "frames": 300
// }
//
// Without "solver", a scene with colliders or a ground, or with a "material", solves with the
// fast settings (use_fast_settings), as the built-in contact scenes do; the lab's cloth
// without either, with the lab's solver (implicit-pcg to 1e-6). OBJ paths are relative to the
// scene file's folder.
#include <filesystem>
#include <string_view>

#include "animkit/cloth/cloth_world.h"
#include "animkit/core/result.h"

namespace animkit {

/// Largest scene file read.
constexpr std::uintmax_t kMaxSceneFileBytes = 16u << 20;

/// The scene in JSON `text`. `name` (the file's) starts every error, which names the key by
/// its path ("scene.json: colliders[1].radius: expected a number, got \"big\""). OBJ files
/// named in it are read from `folder`. The result is validated (ClothWorldDesc::validate).
Result<ClothWorldDesc> parse_cloth_scene(std::string_view text, std::string_view name,
                                         const std::filesystem::path& folder);

/// parse_cloth_scene of the file's bytes, OBJ paths relative to its folder; also errors for
/// a missing, unreadable or huge file.
Result<ClothWorldDesc> read_cloth_scene(const std::filesystem::path& path);

}  // namespace animkit
