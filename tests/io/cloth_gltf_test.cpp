// cloth.glb read back by tinygltf (an independent reader): the mesh, one morph target per frame
// whose STEP weights give back every frame's positions, the colliders' node animation, and the
// refusals. The Khronos validator, three.js and Blender check the files the CLI writes
// (tests/gltf/).
#include "animkit/io/cloth_gltf.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../support/gltf_accessors.h"

namespace animkit {
namespace {

using testing::accessor_floats;
using testing::load_glb;

// A sheet of 3 x 3 vertices (8 triangles) folding over `frames` frames beside a ball moving along x
// and a still ground.
ClothAnimation folding_sheet(int frames) {
  ClothAnimation a;
  a.vertex_count = 9;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      const int v = 3 * i + j;
      a.triangles.push_back({v, v + 3, v + 1});
      a.triangles.push_back({v + 1, v + 3, v + 4});
    }
  }
  a.frame_time = 0.04;
  for (int f = 0; f < frames; ++f) {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const double angle = 0.3 * f * (j - 1);
        a.positions.push_back(static_cast<float>(0.5 * (j - 1) * std::cos(angle)));
        a.positions.push_back(static_cast<float>(1.0 + 0.5 * std::abs(j - 1) * std::sin(angle)));
        a.positions.push_back(static_cast<float>(0.5 * i - 0.01 * f));
      }
    }
  }
  ClothAnimation::ColliderTrack ball{.name = "ball", .surface = {}, .poses = {}};
  ball.surface.vertices = {Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0, 0.1, 0), Vec3(0, 0, 0.1)};
  ball.surface.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  ClothAnimation::ColliderTrack ground{.name = "ground", .surface = ball.surface, .poses = {}};
  for (int f = 0; f < frames; ++f) {
    RigidPose pose;
    pose.position = Vec3(0.1 * f, 0.5, 0);
    pose.rotation = Quat(Eigen::AngleAxisd(0.2 * f, Vec3::UnitY()));
    ball.poses.push_back(pose);
    ground.poses.push_back(RigidPose{});
  }
  a.colliders = {ball, ground};
  return a;
}

TEST(ClothGltf, EveryFrameComesBackFromItsMorphTargetAndStepWeights) {
  const int frames = 6;
  const ClothAnimation a = folding_sheet(frames);
  const auto bytes = cloth_glb(a);
  ASSERT_TRUE(bytes) << bytes.error().message;
  const tinygltf::Model model = load_glb(*bytes);
  EXPECT_EQ(model.asset.version, "2.0");
  ASSERT_EQ(model.meshes.size(), 3u);  // the cloth and two colliders
  const tinygltf::Primitive& sheet = model.meshes[0].primitives.at(0);
  ASSERT_EQ(sheet.targets.size(), static_cast<std::size_t>(frames - 1));
  const auto base = accessor_floats(model, sheet.attributes.at("POSITION"));
  ASSERT_EQ(base.size(), 27u);
  EXPECT_EQ(accessor_floats(model, sheet.attributes.at("NORMAL")).size(), 27u);

  // The weights animation: STEP, keyed at every frame's time, one-hot on frame k's target.
  ASSERT_EQ(model.animations.size(), 1u);
  const tinygltf::Animation& animation = model.animations[0];
  const tinygltf::AnimationChannel* weights = nullptr;
  for (const auto& channel : animation.channels)
    if (channel.target_path == "weights") weights = &channel;
  ASSERT_NE(weights, nullptr);
  EXPECT_EQ(weights->target_node, 0);
  const tinygltf::AnimationSampler& sampler = animation.samplers.at(weights->sampler);
  EXPECT_EQ(sampler.interpolation, "STEP");
  const auto times = accessor_floats(model, sampler.input);
  const auto table = accessor_floats(model, sampler.output);
  ASSERT_EQ(times.size(), static_cast<std::size_t>(frames));
  ASSERT_EQ(table.size(), static_cast<std::size_t>(frames * (frames - 1)));

  for (int f = 0; f < frames; ++f) {
    EXPECT_FLOAT_EQ(times[f], static_cast<float>(f * a.frame_time));
    std::vector<float> x = base;
    for (int t = 0; t < frames - 1; ++t) {
      const float w = table[f * (frames - 1) + t];
      EXPECT_EQ(w, t == f - 1 ? 1.0f : 0.0f) << "frame " << f << " target " << t;
      if (w == 0.0f) continue;
      const auto delta = accessor_floats(model, sheet.targets[t].at("POSITION"));
      for (std::size_t i = 0; i < x.size(); ++i) x[i] += w * delta[i];
    }
    for (std::size_t i = 0; i < x.size(); ++i) {
      EXPECT_NEAR(x[i], a.positions[f * 27 + i], 1e-6) << "frame " << f << " value " << i;
    }
  }
}

TEST(ClothGltf, AMovingColliderIsANodeAnimationAndAStillOneIsNot) {
  const ClothAnimation a = folding_sheet(4);
  const tinygltf::Model model = load_glb(*cloth_glb(a));
  ASSERT_EQ(model.nodes.size(), 3u);
  EXPECT_EQ(model.nodes[1].name, "ball");
  EXPECT_EQ(model.nodes[2].name, "ground");
  const tinygltf::Animation& animation = model.animations.at(0);
  int ball_channels = 0;
  for (const auto& channel : animation.channels) {
    EXPECT_NE(channel.target_node, 2) << "the still ground is animated";
    if (channel.target_node != 1) continue;
    ++ball_channels;
    const tinygltf::AnimationSampler& sampler = animation.samplers.at(channel.sampler);
    const auto values = accessor_floats(model, sampler.output);
    for (int f = 0; f < 4; ++f) {
      const RigidPose& pose = a.colliders[0].poses[f];
      if (channel.target_path == "translation") {
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(values[3 * f + k], pose.position[k], 1e-6);
      } else {
        ASSERT_EQ(channel.target_path, "rotation");
        const Quat q(values[4 * f + 3], values[4 * f], values[4 * f + 1], values[4 * f + 2]);
        EXPECT_NEAR(std::abs(q.dot(pose.rotation)), 1.0, 1e-6) << "frame " << f;
      }
    }
  }
  EXPECT_EQ(ball_channels, 2);
  // The collider's mesh is its own surface, placed by its node.
  const tinygltf::Primitive& ball = model.meshes.at(model.nodes[1].mesh).primitives.at(0);
  EXPECT_EQ(accessor_floats(model, ball.attributes.at("POSITION")).size(), 12u);
}

TEST(ClothGltf, OneFrameIsAStillMeshWithoutAnimation) {
  const tinygltf::Model model = load_glb(*cloth_glb(folding_sheet(1)));
  EXPECT_TRUE(model.meshes[0].primitives[0].targets.empty());
  EXPECT_TRUE(model.animations.empty());
}

TEST(ClothGltf, BadAnimationsAndTooManyFramesAreRefused) {
  ClothAnimation a = folding_sheet(3);
  a.positions.pop_back();
  EXPECT_EQ(cloth_glb(a).error().message,
            "cannot write glTF: the positions are not whole frames of the cloth's vertices");
  a = folding_sheet(3);
  a.colliders[0].poses.pop_back();
  EXPECT_EQ(cloth_glb(a).error().message,
            "cannot write glTF: collider 'ball' has 2 poses for 3 frames");
  a = folding_sheet(3);
  a.triangles[0][1] = 9;
  EXPECT_EQ(cloth_glb(a).error().message,
            "cannot write glTF: a triangle names a vertex out of range");
  a = folding_sheet(3);
  a.frame_time = 0.0;
  EXPECT_FALSE(cloth_glb(a));
  EXPECT_EQ(cloth_glb_fits(9, 65536)->message,
            "a cloth.glb holds at most 65535 frames (one morph target each), not 65536");
  EXPECT_EQ(cloth_glb_fits(10201, 20000)->message,
            "a cloth.glb of 20000 frames of 10201 vertices would pass glTF's 4 GiB");
  EXPECT_FALSE(cloth_glb_fits(10201, 600));
}

}  // namespace
}  // namespace animkit
