// Prepares the Blender round trip (bvh_roundtrip_check.py): reads a BVH file in metres
// (--scale as the CMU data needs), writes it back with animkit's writer, and writes the joint
// positions animkit's FK gives at a few frames, for Blender to compare its import against.
//   usage: animkit_bvh_blender_fixture IN.bvh OUT_DIR   -> OUT_DIR/roundtrip.{bvh,json}
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "animkit/io/atomic_write.h"
#include "animkit/io/bvh.h"

int main(int argc, char** argv) {
  using namespace animkit;
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s IN.bvh OUT_DIR\n", argv[0]);
    return 2;
  }
  // The CMU database's unit is about 0.056444 m (its FAQ): Blender then sees a human in metres.
  const auto clip = read_bvh_file(argv[1], {.scale = 0.056444});
  if (!clip) {
    std::fprintf(stderr, "%s\n", clip.error().message.c_str());
    return 1;
  }
  const std::filesystem::path dir = argv[2];
  if (auto made = ensure_output_directory(dir); !made) {
    std::fprintf(stderr, "%s\n", made.error().message.c_str());
    return 1;
  }
  const Skeleton skeleton = *build_skeleton(clip->skeleton);
  SkeletonPose pose = skeleton_rest_pose(skeleton);
  nlohmann::json expected;
  // Blender makes a bone per joint; End Sites only set their parent's tail.
  for (int j = 0; j < clip->joint_count(); ++j) {
    if (!clip->end_sites[j]) expected["bones"].push_back(clip->skeleton.names[j]);
  }
  const int last = clip->frame_count() - 1;
  for (const int frame : {0, last / 4, last / 2, last}) {
    if (frame < 0) continue;
    bvh_frame_to_pose(*clip, frame, pose);
    skeleton_forward_kinematics(skeleton, pose);
    nlohmann::json heads;
    for (int j = 0; j < clip->joint_count(); ++j) {
      const Vec3& p = pose.global_positions[j];
      if (!clip->end_sites[j]) heads[clip->skeleton.names[j]] = {p.x(), p.y(), p.z()};
    }
    expected["frames"].push_back({{"frame", frame}, {"heads", heads}});
  }
  // Blender stores bones and keys in single precision: 0.1 mm on a 2 m figure.
  expected["tolerance"] = 1e-4;
  if (auto written = write_bvh_file(dir / "roundtrip.bvh", *clip); !written) {
    std::fprintf(stderr, "%s\n", written.error().message.c_str());
    return 1;
  }
  if (auto written = write_file_atomic(dir / "roundtrip.json", expected.dump(1)); !written) {
    std::fprintf(stderr, "%s\n", written.error().message.c_str());
    return 1;
  }
  std::printf("wrote %s and roundtrip.json\n", (dir / "roundtrip.bvh").c_str());
  return 0;
}
