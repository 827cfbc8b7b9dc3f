#pragma once
// A cloth run as glTF 2.0 (.glb: one file with its buffers), the format web viewers, three.js,
// Godot, Unity and Blender all read. The sheet is one mesh with normals; its motion is one morph
// target per frame (positions and normals relative to the first frame) whose weights a STEP
// animation turns on one at a time, the layout Blender, three.js and Godot 4 import as shape keys
// or morph targets. Each collider is a mesh of its own whose rigid motion animates its node.
// Units are metres and +Y is up, as glTF requires (section 3.4, "Coordinate System and Units"),
// and as animkit's cloth scenes already are. Size: about 24 bytes x vertices x frames (a 41 x 41
// sheet over 60 frames: 2.5 MB).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "animkit/collision/collider_motion.h"
#include "animkit/core/result.h"
#include "animkit/core/triangle_mesh.h"

namespace animkit {

/// What cloth.glb holds.
struct ClothAnimation {
  int vertex_count = 0;                       ///< vertices of the sheet
  std::vector<std::array<int, 3>> triangles;  ///< the sheet's triangles, 0-based vertex indices
  double frame_time = 1.0 / 60.0;  ///< seconds between frames (> 0)
  /// Frame after frame, vertex_count x (x, y, z) each; frame 0 is the mesh as it starts.
  std::vector<float> positions;

  /// One collider: its surface and its rigid pose at every frame.
  struct ColliderTrack {
    std::string name;              ///< names its glTF mesh and node
    TriangleMesh surface;          ///< in the collider's own frame
    std::vector<RigidPose> poses;  ///< one per frame
  };
  std::vector<ColliderTrack> colliders;  ///< each with one pose per frame; may be empty

  /// Whole frames in `positions` (0 without vertices).
  int frame_count() const {
    return vertex_count > 0 ? static_cast<int>(positions.size() / (3 * vertex_count)) : 0;
  }
};

/// The frame times a .glb's keyframes hold as distinct, finite float seconds over 65,535 frames.
inline constexpr double kMinGltfFrameTime = 1e-9, kMaxGltfFrameTime = 1e6;

/// Most frames a cloth.glb holds: one morph target each, and a weight table of frames^2 entries
/// whose indices must fit 32 bits.
inline constexpr int kMaxGltfClothFrames = 65535;

/// Whether `frames` frames of a sheet of `vertex_count` vertices fit a .glb (at most
/// kMaxGltfClothFrames, and 4 GiB at about 24 bytes a vertex and frame): checked before a run,
/// so that a long simulation does not end in a file that cannot be written.
std::optional<Error> cloth_glb_fits(int vertex_count, long long frames);

/// The .glb bytes. Errors: no frames, sizes that disagree, a frame time outside
/// kMinGltfFrameTime..kMaxGltfFrameTime, a file past glTF's 4 GiB.
Result<std::string> cloth_glb(const ClothAnimation& animation);

}  // namespace animkit
