#pragma once
// A BVH skeleton as an Orocos KDL tree, for the benchmarks that compare with KDL (tree_ik_bench,
// footlock_bench; only they link KDL). Each non-root joint becomes a fixed segment carrying its
// rest offset, then one revolute segment per rotation channel in the file's order, so a frame's
// Euler angles are KDL's joint values. The tree's root segment is the skeleton's root in its own
// frame: its translation and rotation channels are not KDL joints, so KDL positions are in the
// root's frame (world = root rotation * KDL + root position).
#include <kdl/frames.hpp>
#include <kdl/jntarray.hpp>
#include <kdl/tree.hpp>
#include <string>
#include <vector>

#include "animkit/core/types.h"
#include "animkit/io/bvh.h"
#include "animkit/kinematics/skeleton.h"

namespace animkit::bench {

inline KDL::Vector kdl(const Vec3& v) {
  return KDL::Vector(v.x(), v.y(), v.z());
}

struct KdlModel {
  KDL::Tree tree;
  std::vector<std::string> tips;  ///< per animkit joint: the KDL segment ending at it
  std::vector<int> first_q;       ///< per animkit joint: its first KDL joint value, -1 if none
  unsigned joints = 0;
};

/// The KDL tree of `skeleton` (built from `bvh`'s hierarchy) with `bvh`'s rotation channels as
/// joints. One root (the first joint).
KdlModel kdl_model(const BvhClip& bvh, const Skeleton& skeleton);

/// KDL's joint values of BVH frame `frame`: the rotation channels in radians, in segment order.
KDL::JntArray kdl_frame(const BvhClip& bvh, const KdlModel& model, int frame);

}  // namespace animkit::bench
