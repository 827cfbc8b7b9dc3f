#include "kdl_skeleton.h"

#include <numbers>

namespace animkit::bench {

namespace {

bool is_rotation(BvhChannel ch) {
  return ch == BvhChannel::x_rotation || ch == BvhChannel::y_rotation ||
         ch == BvhChannel::z_rotation;
}

}  // namespace

KdlModel kdl_model(const BvhClip& bvh, const Skeleton& s) {
  const std::string root = s.names()[0];
  KdlModel m{KDL::Tree(root), {}, {}, 0};
  m.tips.assign(static_cast<std::size_t>(s.joint_count()), root);
  m.first_q.assign(static_cast<std::size_t>(s.joint_count()), -1);
  for (int j = 0; j < s.joint_count(); ++j) {
    const auto uj = static_cast<std::size_t>(j);
    const int p = s.parents()[uj];
    if (p < 0) continue;
    std::string parent = m.tips[static_cast<std::size_t>(p)];
    const std::string& name = s.names()[uj];
    m.tree.addSegment(KDL::Segment(name + "_offset", KDL::Joint(KDL::Joint::None),
                                   KDL::Frame(kdl(s.rest_offsets()[uj]))),
                      parent);
    parent = name + "_offset";
    for (const BvhChannel ch : bvh.channels[uj]) {
      if (!is_rotation(ch)) continue;
      const auto type = ch == BvhChannel::x_rotation   ? KDL::Joint::RotX
                        : ch == BvhChannel::y_rotation ? KDL::Joint::RotY
                                                       : KDL::Joint::RotZ;
      const std::string segment = name + "_" + std::string(bvh_channel_name(ch));
      if (m.first_q[uj] < 0) m.first_q[uj] = static_cast<int>(m.joints);
      m.tree.addSegment(KDL::Segment(segment, KDL::Joint(segment, type)), parent);
      parent = segment;
      ++m.joints;
    }
    m.tips[uj] = parent;
  }
  return m;
}

KDL::JntArray kdl_frame(const BvhClip& bvh, const KdlModel& m, int frame) {
  KDL::JntArray q(m.joints);
  int column = 0;
  for (std::size_t j = 0; j < bvh.channels.size(); ++j) {
    int k = m.first_q[j];
    for (const BvhChannel ch : bvh.channels[j]) {
      if (is_rotation(ch) && k >= 0) q(k++) = bvh.motion(frame, column) * std::numbers::pi / 180.0;
      ++column;
    }
  }
  return q;
}

}  // namespace animkit::bench
