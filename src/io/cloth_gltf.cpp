#include "animkit/io/cloth_gltf.h"

#include <cmath>
#include <cstdint>
#include <span>

#include "glb_builder.h"

namespace animkit {

namespace {

using Json = nlohmann::ordered_json;

std::array<float, 4> quaternion_xyzw(const Quat& q) {
  const Quat n = q.normalized();
  return {static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z()),
          static_cast<float>(n.w())};
}

std::optional<Error> check(const ClothAnimation& a) {
  if (a.vertex_count <= 0) return Error{"the cloth has no vertices"};
  if (a.triangles.empty()) return Error{"the cloth has no triangles"};
  if (!(a.frame_time >= kMinGltfFrameTime && a.frame_time <= kMaxGltfFrameTime))
    return Error{"the frame time must be between 1e-09 and 1e+06 s"};
  if (a.positions.empty() || a.positions.size() % (3 * static_cast<std::size_t>(a.vertex_count)))
    return Error{"the positions are not whole frames of the cloth's vertices"};
  for (const auto& t : a.triangles)
    for (int v : t)
      if (v < 0 || v >= a.vertex_count) return Error{"a triangle names a vertex out of range"};
  for (const auto& c : a.colliders) {
    if (c.poses.size() != static_cast<std::size_t>(a.frame_count()))
      return Error{"collider '" + c.name + "' has " + std::to_string(c.poses.size()) +
                   " poses for " + std::to_string(a.frame_count()) + " frames"};
  }
  return std::nullopt;
}

// One collider: a mesh in its own frame, its node placed at the first pose and, when it moves,
// animated (translation and rotation sampled every frame; the quaternions kept on one
// hemisphere so that interpolation turns the short way).
void add_collider(GlbBuilder& glb, const ClothAnimation::ColliderTrack& c, int input,
                  Json& channels, Json& samplers) {
  Json& doc = glb.document();
  std::vector<float> local;
  for (const Vec3& p : c.surface.vertices)
    for (int k = 0; k < 3; ++k) local.push_back(static_cast<float>(p[k]));
  const int position = glb.add_floats(local, "VEC3", 3, true, GlbBuilder::kArrayBuffer);
  const int normal = glb.add_floats(gltf_vertex_normals(local, c.surface.triangles), "VEC3", 3,
                                    false, GlbBuilder::kArrayBuffer);
  const int indices = glb.add_indices(gltf_indices(c.surface.triangles));
  doc["meshes"].push_back({{"name", c.name},
                           {"primitives",
                            {{{"attributes", {{"POSITION", position}, {"NORMAL", normal}}},
                              {"indices", indices},
                              {"material", 1}}}}});
  const int mesh = static_cast<int>(doc["meshes"].size()) - 1;
  const RigidPose& first = c.poses.front();
  const auto xyz = [](const Vec3& v) {
    return std::array<float, 3>{static_cast<float>(v.x()), static_cast<float>(v.y()),
                                static_cast<float>(v.z())};
  };
  doc["nodes"].push_back({{"name", c.name},
                          {"mesh", mesh},
                          {"translation", xyz(first.position)},
                          {"rotation", quaternion_xyzw(first.rotation)}});
  const int node = static_cast<int>(doc["nodes"].size()) - 1;
  bool moves = false;
  for (const RigidPose& pose : c.poses) {
    moves = moves || !pose.position.isApprox(first.position, 0.0) ||
            !pose.rotation.coeffs().isApprox(first.rotation.coeffs(), 0.0);
  }
  if (!moves) return;
  std::vector<float> translations, rotations;
  Quat previous = first.rotation;
  for (const RigidPose& pose : c.poses) {
    for (float v : xyz(pose.position)) translations.push_back(v);
    Quat q = pose.rotation;
    if (q.coeffs().dot(previous.coeffs()) < 0.0) q.coeffs() = -q.coeffs();
    previous = q;
    for (float v : quaternion_xyzw(q)) rotations.push_back(v);
  }
  const int translation = glb.add_floats(translations, "VEC3", 3, false, 0);
  const int rotation = glb.add_floats(rotations, "VEC4", 4, false, 0);
  for (const auto& [output, path] :
       {std::pair{translation, "translation"}, std::pair{rotation, "rotation"}}) {
    samplers.push_back({{"input", input}, {"output", output}, {"interpolation", "LINEAR"}});
    channels.push_back({{"sampler", static_cast<int>(samplers.size()) - 1},
                        {"target", {{"node", node}, {"path", path}}}});
  }
}

}  // namespace

std::optional<Error> cloth_glb_fits(int vertex_count, long long frames) {
  if (frames > kMaxGltfClothFrames) {
    return Error{"a cloth.glb holds at most " + std::to_string(kMaxGltfClothFrames) +
                 " frames (one morph target each), not " + std::to_string(frames)};
  }
  // Positions and normals, 12 bytes each, per vertex and frame; the JSON and the collider
  // meshes stay far below the rest.
  const double bytes = 24.0 * vertex_count * static_cast<double>(frames);
  if (bytes > 4e9) {
    return Error{"a cloth.glb of " + std::to_string(frames) + " frames of " +
                 std::to_string(vertex_count) + " vertices would pass glTF's 4 GiB"};
  }
  return std::nullopt;
}

Result<std::string> cloth_glb(const ClothAnimation& a) {
  if (auto problem = check(a)) return fail("cannot write glTF: " + problem->message);
  if (auto problem = cloth_glb_fits(a.vertex_count, a.frame_count()))
    return fail("cannot write glTF: " + problem->message);
  const std::size_t frame_floats = 3 * static_cast<std::size_t>(a.vertex_count);
  const int frames = a.frame_count();
  const int targets = frames - 1;  // frame 0 is the mesh itself
  const auto frame = [&](int k) {
    return std::span<const float>(a.positions).subspan(k * frame_floats, frame_floats);
  };

  GlbBuilder glb("animkit");
  Json& doc = glb.document();
  doc["materials"] = Json::array({gltf_material("cloth", {0.8, 0.35, 0.25, 1.0}, true)});
  if (!a.colliders.empty()) {
    doc["materials"].push_back(gltf_material("collider", {0.6, 0.6, 0.62, 1.0}, false));
  }
  doc["meshes"] = Json::array();
  doc["nodes"] = Json::array();

  const std::vector<float> base_normals = gltf_vertex_normals(frame(0), a.triangles);
  const int position = glb.add_floats(frame(0), "VEC3", 3, true, GlbBuilder::kArrayBuffer);
  const int normal = glb.add_floats(base_normals, "VEC3", 3, false, GlbBuilder::kArrayBuffer);
  const int indices = glb.add_indices(gltf_indices(a.triangles));

  // Frame k's target: positions and normals relative to frame 0 (glTF section 3.7.2.2,
  // "Morph Targets": the attribute is the base plus the weighted sum of the targets').
  Json primitive_targets = Json::array();
  Json target_names = Json::array();
  std::vector<float> delta(frame_floats);
  for (int k = 1; k < frames; ++k) {
    const auto now = frame(k);
    for (std::size_t i = 0; i < frame_floats; ++i) delta[i] = now[i] - frame(0)[i];
    const int target_position = glb.add_floats(delta, "VEC3", 3, true, GlbBuilder::kArrayBuffer);
    const std::vector<float> normals = gltf_vertex_normals(now, a.triangles);
    for (std::size_t i = 0; i < frame_floats; ++i) delta[i] = normals[i] - base_normals[i];
    const int target_normal = glb.add_floats(delta, "VEC3", 3, false, GlbBuilder::kArrayBuffer);
    primitive_targets.push_back({{"POSITION", target_position}, {"NORMAL", target_normal}});
    target_names.push_back("frame " + std::to_string(k));
  }
  Json primitive = {{"attributes", {{"POSITION", position}, {"NORMAL", normal}}},
                    {"indices", indices},
                    {"material", 0}};
  Json mesh = {{"name", "cloth"}};
  if (targets > 0) {
    primitive["targets"] = primitive_targets;
    mesh["weights"] = std::vector<float>(targets, 0.0f);
    mesh["extras"] = {{"targetNames", target_names}};  // the names Blender and three.js show
  }
  mesh["primitives"] = Json::array({primitive});
  doc["meshes"].push_back(mesh);
  doc["nodes"].push_back({{"name", "cloth"}, {"mesh", 0}});

  Json channels = Json::array(), samplers = Json::array();
  int input = -1;
  if (frames > 1) {
    std::vector<float> times;
    for (int k = 0; k < frames; ++k) times.push_back(static_cast<float>(k * a.frame_time));
    input = glb.add_floats(times, "SCALAR", 1, true, 0);
  }
  if (targets > 0) {
    // Weights at keyframe k: target k-1 at 1, every other 0 (frame 0: all 0), held until the
    // next keyframe (STEP): exactly the simulated positions at every frame, no blending.
    std::vector<std::uint32_t> ones;
    for (int k = 1; k < frames; ++k) {
      ones.push_back(static_cast<std::uint32_t>(static_cast<std::size_t>(k) * targets + (k - 1)));
    }
    const std::vector<float> values(ones.size(), 1.0f);
    const int weights =
        glb.add_sparse_floats(static_cast<std::size_t>(frames) * targets, ones, values);
    samplers.push_back({{"input", input}, {"output", weights}, {"interpolation", "STEP"}});
    channels.push_back({{"sampler", 0}, {"target", {{"node", 0}, {"path", "weights"}}}});
  }
  for (const auto& collider : a.colliders) add_collider(glb, collider, input, channels, samplers);

  Json scene_nodes = Json::array();
  for (std::size_t n = 0; n < doc["nodes"].size(); ++n) scene_nodes.push_back(n);
  doc["scenes"] = {{{"name", "animkit cloth"}, {"nodes", scene_nodes}}};
  doc["scene"] = 0;
  if (!channels.empty()) {
    doc["animations"] = {{{"name", "cloth"}, {"channels", channels}, {"samplers", samplers}}};
  }
  return glb.glb();
}

}  // namespace animkit
