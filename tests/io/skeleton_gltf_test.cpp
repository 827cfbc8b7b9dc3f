// A skeleton's glTF read back by tinygltf (an independent reader): the node tree, the joints'
// positions at every frame from the node animation against animkit's forward kinematics (in
// metres), the skin's bind matrices against the rest pose, and the refusals.
#include "animkit/io/skeleton_gltf.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "../support/gltf_accessors.h"
#include "animkit/io/bvh_motion.h"

namespace animkit {
namespace {

using testing::accessor_floats;
using testing::load_glb;

// A leg in centimetres: hip (moving root), knee, ankle, toe; the hip walks along z and turns,
// the knee bends.
struct Leg {
  SkeletonDesc skeleton;
  SkeletalMotion motion;
};

Leg bending_leg(int frames) {
  Leg leg;
  leg.skeleton.add_joint("Hip", -1, Vec3(0, 90, 0));
  leg.skeleton.add_joint("Knee", 0, Vec3(0, -45, 0));
  leg.skeleton.add_joint("Ankle", 1, Vec3(0, -42, 0));
  leg.skeleton.add_joint("Toe", 2, Vec3(0, -3, 12));
  leg.motion = make_motion(4, frames, 1.0 / 30.0);
  for (int f = 0; f < frames; ++f) {
    const std::size_t i = static_cast<std::size_t>(f) * 4;
    leg.motion.local_translations[i] = Vec3(0, 90, 5.0 * f);
    leg.motion.local_rotations[i] = Quat(Eigen::AngleAxisd(0.1 * f, Vec3::UnitY()));
    for (int j = 1; j < 4; ++j) leg.motion.local_translations[i + j] = leg.skeleton.rest_offsets[j];
    leg.motion.local_rotations[i + 1] = Quat(Eigen::AngleAxisd(0.2 * f, Vec3::UnitX()));
  }
  return leg;
}

// A node's local transform at keyframe f: its animated channels, else its own TRS.
Eigen::Affine3d node_at(const tinygltf::Model& model, int node, int f) {
  const tinygltf::Node& n = model.nodes.at(node);
  Vec3 t(n.translation[0], n.translation[1], n.translation[2]);
  Quat r(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);
  for (const auto& animation : model.animations) {
    for (const auto& channel : animation.channels) {
      if (channel.target_node != node) continue;
      const auto values = accessor_floats(model, animation.samplers.at(channel.sampler).output);
      if (channel.target_path == "translation") {
        t = Vec3(values[3 * f], values[3 * f + 1], values[3 * f + 2]);
      } else if (channel.target_path == "rotation") {
        r = Quat(values[4 * f + 3], values[4 * f], values[4 * f + 1], values[4 * f + 2]);
      }
    }
  }
  return Eigen::Translation3d(t) * r.normalized();
}

Eigen::Affine3d global_at(const tinygltf::Model& model, int node, int f) {
  for (std::size_t p = 0; p < model.nodes.size(); ++p) {
    for (int child : model.nodes[p].children) {
      if (child == node) return global_at(model, static_cast<int>(p), f) * node_at(model, node, f);
    }
  }
  return node_at(model, node, f);
}

TEST(SkeletonGltf, TheJointsFollowTheMotionInMetres) {
  const int frames = 5;
  const Leg leg = bending_leg(frames);
  const auto bytes = skeleton_glb(leg.skeleton, leg.motion, 0.01);
  ASSERT_TRUE(bytes) << bytes.error().message;
  const tinygltf::Model model = load_glb(*bytes);
  ASSERT_EQ(model.nodes.size(), 5u);  // four joints and the figure
  EXPECT_EQ(model.nodes[2].name, "Ankle");
  EXPECT_EQ(model.nodes[1].children, std::vector<int>{2});
  const auto skeleton = build_skeleton(leg.skeleton);
  ASSERT_TRUE(skeleton);
  SkeletonPose pose = identity_pose(4);
  for (int f = 0; f < frames; ++f) {
    leg.motion.read_frame(f, pose);
    skeleton_forward_kinematics(*skeleton, pose);
    for (int j = 0; j < 4; ++j) {
      const Vec3 got = global_at(model, j, f).translation();
      EXPECT_LT((got - 0.01 * pose.global_positions[j]).norm(), 1e-6)
          << leg.skeleton.names[j] << " at frame " << f;
    }
  }
  // Times every frame_time apart; the translation animated only on the root.
  const auto& animation = model.animations.at(0);
  int translations = 0;
  for (const auto& channel : animation.channels) {
    if (channel.target_path == "translation") {
      ++translations;
      EXPECT_EQ(channel.target_node, 0);
    }
  }
  EXPECT_EQ(translations, 1);
  const auto times = accessor_floats(model, animation.samplers.at(0).input);
  ASSERT_EQ(times.size(), static_cast<std::size_t>(frames));
  EXPECT_FLOAT_EQ(times.back(), static_cast<float>(4.0 / 30.0));
}

TEST(SkeletonGltf, TheFigureIsSkinnedToTheJointsAtRest) {
  const Leg leg = bending_leg(2);
  const tinygltf::Model model = load_glb(*skeleton_glb(leg.skeleton, leg.motion, 0.01));
  ASSERT_EQ(model.skins.size(), 1u);
  const tinygltf::Skin& skin = model.skins[0];
  EXPECT_EQ(skin.joints, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(skin.skeleton, 0);
  const auto inverse_binds = accessor_floats(model, skin.inverseBindMatrices);
  ASSERT_EQ(inverse_binds.size(), 64u);
  // Each joint's rest transform times its inverse bind matrix is the identity.
  Eigen::Affine3d rest = Eigen::Affine3d::Identity();
  for (int j = 0; j < 4; ++j) {
    rest = rest * Eigen::Translation3d(0.01 * leg.skeleton.rest_offsets[j]);
    const Eigen::Matrix4f inverse = Eigen::Map<const Eigen::Matrix4f>(&inverse_binds[16 * j]);
    EXPECT_TRUE((rest.matrix() * inverse.cast<double>()).isIdentity(1e-6)) << j;
  }
  // Three bones (hip-knee, knee-ankle, ankle-toe), 8 flat triangles each, every vertex bound
  // wholly to one joint, inside the rest skeleton's reach.
  const tinygltf::Node& figure = model.nodes.at(4);
  EXPECT_EQ(figure.skin, 0);
  EXPECT_TRUE(figure.translation.empty() && figure.rotation.empty());
  const tinygltf::Primitive& body = model.meshes.at(figure.mesh).primitives.at(0);
  const auto positions = accessor_floats(model, body.attributes.at("POSITION"));
  const auto weights = accessor_floats(model, body.attributes.at("WEIGHTS_0"));
  EXPECT_EQ(positions.size(), 3u * 3 * 8 * 3);
  for (std::size_t v = 0; v < weights.size() / 4; ++v) EXPECT_EQ(weights[4 * v], 1.0f);
  for (std::size_t v = 0; v < positions.size() / 3; ++v) {
    EXPECT_GT(positions[3 * v + 1], -0.01f);
    EXPECT_LT(positions[3 * v + 1], 0.91f);
  }
}

TEST(SkeletonGltf, BadInputIsRefused) {
  Leg leg = bending_leg(2);
  EXPECT_EQ(skeleton_glb(leg.skeleton, leg.motion, 0.0).error().message,
            "cannot write glTF: metres per unit must be a number > 0");
  SkeletalMotion three = make_motion(3, 2, 1.0 / 30.0);
  EXPECT_EQ(skeleton_glb(leg.skeleton, three, 1.0).error().message,
            "cannot write glTF: the motion has 3 joints and the skeleton 4");
  EXPECT_EQ(skeleton_glb(leg.skeleton, make_motion(4, 0, 1.0 / 30.0), 1.0).error().message,
            "cannot write glTF: the motion has no frames");
  // Keyframe times must be distinct, finite floats.
  for (double frame_time : {1e-50, 1e39}) {
    EXPECT_EQ(skeleton_glb(leg.skeleton, make_motion(4, 2, frame_time), 1.0).error().message,
              "cannot write glTF: the frame time must be between 1e-09 and 1e+06 s");
  }
  BvhClip clip;
  clip.skeleton = leg.skeleton;
  clip.channels.resize(4);
  clip.end_sites.assign(4, false);
  clip.motion.resize(1, 1);  // one value for no channel
  const auto written = write_skeleton_glb_file("/nonexistent/x.glb", clip, 1.0);
  ASSERT_FALSE(written);
  EXPECT_EQ(written.error().message.rfind("/nonexistent/x.glb: ", 0), 0u)
      << written.error().message;
}

}  // namespace
}  // namespace animkit
