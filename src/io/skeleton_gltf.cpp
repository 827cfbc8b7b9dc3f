#include "animkit/io/skeleton_gltf.h"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <vector>

#include "animkit/io/atomic_write.h"
#include "animkit/io/bvh_motion.h"
#include "animkit/io/cloth_gltf.h"
#include "glb_builder.h"

namespace animkit {

namespace {

using Json = nlohmann::ordered_json;

std::array<float, 3> to_floats(const Vec3& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

std::array<float, 4> to_floats(const Quat& q) {
  const Quat n = q.normalized();
  return {static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z()),
          static_cast<float>(n.w())};
}

// The figure: for each bone (a joint and one child, apart), a tapered octahedron from the joint
// to the child, its widest square a sixth of the way along, faces flat (each triangle its own
// three vertices, so normals stay sharp), bound wholly to the joint.
struct Figure {
  std::vector<float> positions, normals;
  std::vector<std::uint16_t> joints;
  std::vector<float> weights;
};

void add_bone(Figure& figure, int joint, const Vec3& head, const Vec3& tail) {
  const Vec3 axis = tail - head;
  const double length = axis.norm();
  const Vec3 u = axis / length;
  const Vec3 a = u.unitOrthogonal(), b = u.cross(a);
  const Vec3 centre = head + length / 6.0 * u;
  const double r = 0.1 * length;
  const Vec3 ring[4] = {centre + r * a, centre + r * b, centre - r * a, centre - r * b};
  const auto triangle = [&](const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    const Vec3 n = (p1 - p0).cross(p2 - p0).normalized();
    for (const Vec3* p : {&p0, &p1, &p2}) {
      for (int k = 0; k < 3; ++k) {
        figure.positions.push_back(static_cast<float>((*p)[k]));
        figure.normals.push_back(static_cast<float>(n[k]));
      }
      for (std::uint16_t j : {static_cast<std::uint16_t>(joint), std::uint16_t{0}, std::uint16_t{0},
                              std::uint16_t{0}})
        figure.joints.push_back(j);
      for (float w : {1.0f, 0.0f, 0.0f, 0.0f}) figure.weights.push_back(w);
    }
  };
  for (int k = 0; k < 4; ++k) {
    const Vec3& p = ring[k];
    const Vec3& q = ring[(k + 1) % 4];
    triangle(head, q, p);  // outward: a, b, -a, -b turn counter-clockwise about u
    triangle(tail, p, q);
  }
}

std::optional<Error> motion_problem(const SkeletonDesc& skeleton, const SkeletalMotion& motion,
                                    double metres_per_unit) {
  if (auto error = skeleton.validate()) return error;
  if (motion.joint_count != skeleton.joint_count()) {
    return Error{"the motion has " + std::to_string(motion.joint_count) +
                 " joints and the skeleton " + std::to_string(skeleton.joint_count())};
  }
  if (motion.frame_count() < 1) return Error{"the motion has no frames"};
  if (motion.local_translations.size() != motion.local_rotations.size())
    return Error{"the motion's rotations and translations differ in number"};
  if (!(motion.frame_time >= kMinGltfFrameTime && motion.frame_time <= kMaxGltfFrameTime))
    return Error{"the frame time must be between 1e-09 and 1e+06 s"};
  if (motion.frame_count() > 10'000'000) return Error{"the motion has more than 10,000,000 frames"};
  if (!(metres_per_unit > 0.0) || !std::isfinite(metres_per_unit))
    return Error{"metres per unit must be a number > 0"};
  if (skeleton.joint_count() > 65535)
    return Error{"a skin holds at most 65535 joints, not " +
                 std::to_string(skeleton.joint_count())};
  return std::nullopt;
}

}  // namespace

Result<std::string> skeleton_glb(const SkeletonDesc& skeleton, const SkeletalMotion& motion,
                                 double metres_per_unit) {
  if (auto problem = motion_problem(skeleton, motion, metres_per_unit)) {
    return fail("cannot write glTF: " + problem->message);
  }
  const int joints = skeleton.joint_count();
  const int frames = motion.frame_count();
  const double s = metres_per_unit;
  const auto rest_rotation = [&](int j) {
    return skeleton.rest_rotations.empty() ? Quat::Identity() : skeleton.rest_rotations[j];
  };

  GlbBuilder glb("animkit");
  Json& doc = glb.document();
  doc["nodes"] = Json::array();
  for (int j = 0; j < joints; ++j) {
    doc["nodes"].push_back({{"name", skeleton.names[j]},
                            {"translation", to_floats(Vec3(s * skeleton.rest_offsets[j]))},
                            {"rotation", to_floats(rest_rotation(j))}});
  }
  Json roots = Json::array();
  for (int j = 0; j < joints; ++j) {
    const int p = skeleton.parents[j];
    if (p < 0) {
      roots.push_back(j);
    } else {
      doc["nodes"][p]["children"].push_back(j);
    }
  }

  // The bind pose: the skeleton at rest, in metres (parents come first).
  std::vector<Eigen::Affine3d> bind(joints);
  for (int j = 0; j < joints; ++j) {
    Eigen::Affine3d local = Eigen::Translation3d(s * skeleton.rest_offsets[j]) * rest_rotation(j);
    bind[j] = skeleton.parents[j] < 0 ? local : bind[skeleton.parents[j]] * local;
  }
  Figure figure;
  for (int j = 0; j < joints; ++j) {
    const int p = skeleton.parents[j];
    if (p < 0) continue;
    const Vec3 head = bind[p].translation(), tail = bind[j].translation();
    if ((tail - head).norm() > 1e-6) add_bone(figure, p, head, tail);
  }
  Json scene_nodes = roots;
  if (!figure.positions.empty()) {
    std::vector<float> inverse_binds;
    for (const Eigen::Affine3d& b : bind) {
      const Eigen::Matrix4d m = b.inverse().matrix();  // column-major, as glTF stores MAT4
      for (int k = 0; k < 16; ++k) inverse_binds.push_back(static_cast<float>(m.data()[k]));
    }
    Json skin = {{"inverseBindMatrices", glb.add_floats(inverse_binds, "MAT4", 16, false, 0)},
                 {"joints", Json::array()}};
    if (roots.size() == 1) skin["skeleton"] = roots.front();  // the joints' common root
    for (int j = 0; j < joints; ++j) skin["joints"].push_back(j);
    doc["skins"] = Json::array({skin});
    const int position =
        glb.add_floats(figure.positions, "VEC3", 3, true, GlbBuilder::kArrayBuffer);
    const int normal = glb.add_floats(figure.normals, "VEC3", 3, false, GlbBuilder::kArrayBuffer);
    const int joint_ids = glb.add_unsigned_shorts(figure.joints, "VEC4", 4);
    const int weights = glb.add_floats(figure.weights, "VEC4", 4, false, GlbBuilder::kArrayBuffer);
    doc["materials"] = Json::array({gltf_material("bone", {0.75, 0.72, 0.65, 1.0}, false)});
    doc["meshes"] = {{{"name", "figure"},
                      {"primitives",
                       {{{"attributes",
                          {{"POSITION", position},
                           {"NORMAL", normal},
                           {"JOINTS_0", joint_ids},
                           {"WEIGHTS_0", weights}}},
                         {"material", 0}}}}}};
    // A skinned mesh's node sits at the root with no transform of its own (glTF section 3.7.3,
    // "Skins": the joints place it).
    doc["nodes"].push_back({{"name", "figure"}, {"mesh", 0}, {"skin", 0}});
    scene_nodes.push_back(joints);
  }
  doc["scenes"] = {{{"name", "animkit skeleton"}, {"nodes", scene_nodes}}};
  doc["scene"] = 0;

  // Every frame keyed: rotations on every joint the motion turns (kept on one hemisphere so
  // that interpolation turns the short way), translations where the motion moves a joint.
  std::vector<float> times;
  for (int f = 0; f < frames; ++f) times.push_back(static_cast<float>(f * motion.frame_time));
  Json channels = Json::array(), samplers = Json::array();
  int input = -1;
  // Translations carry their bounds (where the figure goes); rotations need none.
  const auto add_channel = [&](int node, const char* path, std::vector<float> values,
                               const char* type, int components) {
    if (input < 0) input = glb.add_floats(times, "SCALAR", 1, true, 0);
    const bool bounds = components == 3;
    samplers.push_back({{"input", input},
                        {"output", glb.add_floats(values, type, components, bounds, 0)},
                        {"interpolation", "LINEAR"}});
    channels.push_back({{"sampler", static_cast<int>(samplers.size()) - 1},
                        {"target", {{"node", node}, {"path", path}}}});
  };
  for (int j = 0; j < joints; ++j) {
    bool turns = false, moves = false;
    for (int f = 0; f < frames; ++f) {
      const std::size_t i = static_cast<std::size_t>(f) * joints + j;
      turns = turns || !motion.local_rotations[i].coeffs().isApprox(rest_rotation(j).coeffs(), 0.0);
      moves = moves || motion.local_translations[i] != skeleton.rest_offsets[j];
    }
    if (turns) {
      std::vector<float> rotations;
      Quat previous = rest_rotation(j);
      for (int f = 0; f < frames; ++f) {
        Quat q = motion.local_rotations[static_cast<std::size_t>(f) * joints + j];
        if (q.coeffs().dot(previous.coeffs()) < 0.0) q.coeffs() = -q.coeffs();
        previous = q;
        for (float v : to_floats(q)) rotations.push_back(v);
      }
      add_channel(j, "rotation", std::move(rotations), "VEC4", 4);
    }
    if (moves) {
      std::vector<float> translations;
      for (int f = 0; f < frames; ++f) {
        const Vec3& t = motion.local_translations[static_cast<std::size_t>(f) * joints + j];
        for (float v : to_floats(Vec3(s * t))) translations.push_back(v);
      }
      add_channel(j, "translation", std::move(translations), "VEC3", 3);
    }
  }
  if (!channels.empty()) {
    doc["animations"] = {{{"name", "motion"}, {"channels", channels}, {"samplers", samplers}}};
  }
  return glb.glb();
}

Result<void> write_skeleton_glb_file(const std::filesystem::path& path, const BvhClip& clip,
                                     double metres_per_unit) {
  if (auto error = clip.validate()) return fail(path.string() + ": " + error->message);
  auto bytes = skeleton_glb(clip.skeleton, motion_from_bvh(clip), metres_per_unit);
  if (!bytes) return fail(path.string() + ": " + bytes.error().message);
  return write_file_atomic(path, *bytes);
}

}  // namespace animkit
