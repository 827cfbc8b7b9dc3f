#include "animkit/kinematics/chain.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "animkit/core/validation.h"
#include "animkit/kinematics/forward_kinematics.h"

namespace animkit {

ChainDesc ChainDesc::from_rest_positions(std::span<const Vec3> world_positions) {
  ChainDesc desc;
  desc.local_offsets.reserve(world_positions.size());
  for (std::size_t i = 0; i < world_positions.size(); ++i) {
    desc.local_offsets.push_back(i == 0 ? world_positions[0]
                                        : Vec3(world_positions[i] - world_positions[i - 1]));
  }
  return desc;
}

std::optional<Error> ChainDesc::validate() const {
  const std::size_t n = local_offsets.size();
  if (n < 2) {
    return Error{"a chain needs at least 2 joints, got " + std::to_string(n)};
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_finite(local_offsets[i])) {
      return Error{"joint " + std::to_string(i) + " offset has a non-finite coordinate " +
                   to_string(local_offsets[i])};
    }
    if (i > 0 && local_offsets[i].norm() < kMinBoneLength) {
      return Error{"bone " + std::to_string(i) + " has zero length"};
    }
  }
  if (!local_rotations.empty() && local_rotations.size() != n) {
    return Error{"local_rotations has " + std::to_string(local_rotations.size()) + " entries for " +
                 std::to_string(n) + " joints"};
  }
  for (std::size_t i = 0; i < local_rotations.size(); ++i) {
    const Quat& q = local_rotations[i];
    if (!is_finite(q)) {
      return Error{"joint " + std::to_string(i) + " rotation has a non-finite component"};
    }
    if (std::abs(q.norm() - 1.0) > kUnitTolerance) {
      return Error{"joint " + std::to_string(i) + " rotation is not a unit quaternion (norm " +
                   format_number(q.norm()) + ")"};
    }
  }
  return std::nullopt;
}

ChainDesc lab_arm() {
  const Vec3 rest[] = {
      {0.0, 1.7, 0.0}, {0.0, 0.9, 0.0}, {0.0, 0.5, 0.0}, {0.0, 0.3, 0.0}, {0.0, -0.9, 0.0}};
  return ChainDesc::from_rest_positions(rest);
}

Result<Chain> build_chain(const ChainDesc& desc) {
  if (auto error = desc.validate()) return fail(error->message);
  Chain chain;
  const std::size_t n = desc.local_offsets.size();
  chain.local_offsets_ = desc.local_offsets;
  chain.rest_rotations_ =
      desc.local_rotations.empty() ? std::vector<Quat>(n, Quat::Identity()) : desc.local_rotations;
  for (Quat& q : chain.rest_rotations_) q.normalize();  // remove the tolerated 1e-6 drift
  chain.bone_lengths_.assign(n, 0.0);
  double longest = 0.0;
  for (std::size_t i = 1; i < n; ++i) {
    chain.bone_lengths_[i] = desc.local_offsets[i].norm();
    chain.reach_ += chain.bone_lengths_[i];
    longest = std::max(longest, chain.bone_lengths_[i]);
  }
  // A bone longer than all the others together leaves a ball around the root out of reach.
  chain.min_reach_ = std::max(0.0, 2.0 * longest - chain.reach_);
  return chain;
}

Pose rest_pose(const Chain& chain) {
  const std::size_t n = chain.local_offsets().size();
  Pose pose{chain.rest_rotations(), std::vector<Quat>(n, Quat::Identity()),
            std::vector<Vec3>(n, Vec3::Zero())};
  forward_kinematics(chain, pose, 0);
  return pose;
}

}  // namespace animkit
