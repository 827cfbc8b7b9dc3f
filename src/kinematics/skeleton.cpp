#include "animkit/kinematics/skeleton.h"

#include <cassert>
#include <cmath>
#include <string>
#include <unordered_map>

#include "animkit/core/validation.h"

namespace animkit {

namespace {
std::string joint_label(const SkeletonDesc& desc, std::size_t i) {
  std::string label = "joint " + std::to_string(i);
  if (i < desc.names.size() && !desc.names[i].empty()) label += " (" + desc.names[i] + ")";
  return label;
}
}  // namespace

int SkeletonDesc::add_joint(std::string name, int parent, const Vec3& rest_offset) {
  names.push_back(std::move(name));
  parents.push_back(parent);
  rest_offsets.push_back(rest_offset);
  if (!rest_rotations.empty()) rest_rotations.push_back(Quat::Identity());
  return joint_count() - 1;
}

std::optional<Error> SkeletonDesc::validate() const {
  const std::size_t n = names.size();
  if (n == 0) return Error{"a skeleton needs at least 1 joint, got 0"};
  if (parents.size() != n) {
    return Error{"parents has " + std::to_string(parents.size()) + " entries for " +
                 std::to_string(n) + " joints"};
  }
  if (rest_offsets.size() != n) {
    return Error{"rest_offsets has " + std::to_string(rest_offsets.size()) + " entries for " +
                 std::to_string(n) + " joints"};
  }
  if (!rest_rotations.empty() && rest_rotations.size() != n) {
    return Error{"rest_rotations has " + std::to_string(rest_rotations.size()) + " entries for " +
                 std::to_string(n) + " joints"};
  }
  std::unordered_map<std::string_view, std::size_t> seen;
  for (std::size_t i = 0; i < n; ++i) {
    if (names[i].empty()) return Error{"joint " + std::to_string(i) + " has an empty name"};
    const auto [it, inserted] = seen.emplace(names[i], i);
    if (!inserted) {
      return Error{"joint " + std::to_string(i) + " is named '" + names[i] + "' like joint " +
                   std::to_string(it->second)};
    }
    const int p = parents[i];
    if (p < -1 || p >= static_cast<int>(i)) {
      return Error{joint_label(*this, i) + " has parent " + std::to_string(p) +
                   "; a parent must come before its child (index in [0, " + std::to_string(i) +
                   ")) or be -1 for a root"};
    }
    if (!is_finite(rest_offsets[i])) {
      return Error{joint_label(*this, i) + " rest offset has a non-finite coordinate " +
                   to_string(rest_offsets[i])};
    }
  }
  for (std::size_t i = 0; i < rest_rotations.size(); ++i) {
    const Quat& q = rest_rotations[i];
    if (!is_finite(q)) {
      return Error{joint_label(*this, i) + " rest rotation has a non-finite component"};
    }
    if (std::abs(q.norm() - 1.0) > kUnitTolerance) {
      return Error{joint_label(*this, i) + " rest rotation is not a unit quaternion (norm " +
                   format_number(q.norm()) + ")"};
    }
  }
  return std::nullopt;
}

SkeletonDesc skeleton_desc_from_chain(const ChainDesc& chain) {
  SkeletonDesc desc;
  const int n = static_cast<int>(chain.local_offsets.size());
  for (int i = 0; i < n; ++i) {
    desc.add_joint("joint" + std::to_string(i), i - 1, chain.local_offsets[i]);
  }
  desc.rest_rotations = chain.local_rotations;
  return desc;
}

int Skeleton::find_joint(std::string_view name) const {
  for (int i = 0; i < joint_count(); ++i) {
    if (names_[i] == name) return i;
  }
  return -1;
}

Result<Skeleton> build_skeleton(const SkeletonDesc& desc) {
  if (auto error = desc.validate()) return fail(error->message);
  Skeleton s;
  const int n = desc.joint_count();
  s.names_ = desc.names;
  s.parents_ = desc.parents;
  s.rest_offsets_ = desc.rest_offsets;
  s.rest_rotations_ =
      desc.rest_rotations.empty() ? std::vector<Quat>(n, Quat::Identity()) : desc.rest_rotations;
  for (Quat& q : s.rest_rotations_) q.normalize();  // remove the tolerated 1e-6 drift
  s.bone_lengths_.assign(n, 0.0);
  // Children as compressed rows: count per parent, prefix sums, then fill in index order.
  s.child_begin_.assign(n + 1, 0);
  for (int i = 0; i < n; ++i) {
    const int p = desc.parents[i];
    if (p < 0) {
      s.roots_.push_back(i);
    } else {
      s.bone_lengths_[i] = desc.rest_offsets[i].norm();
      ++s.child_begin_[p + 1];
    }
  }
  for (int i = 0; i < n; ++i) s.child_begin_[i + 1] += s.child_begin_[i];
  s.child_list_.resize(s.child_begin_[n]);
  std::vector<int> next(s.child_begin_.begin(), s.child_begin_.end() - 1);
  for (int i = 0; i < n; ++i) {
    if (desc.parents[i] >= 0) s.child_list_[next[desc.parents[i]]++] = i;
  }
  for (int i = 0; i < n; ++i) {
    if (s.child_count(i) == 0) s.leaves_.push_back(i);
  }
  return s;
}

SkeletonPose skeleton_rest_pose(const Skeleton& skeleton) {
  const std::size_t n = skeleton.joint_count();
  SkeletonPose pose{skeleton.rest_rotations(), skeleton.rest_offsets(),
                    std::vector<Quat>(n, Quat::Identity()), std::vector<Vec3>(n, Vec3::Zero())};
  skeleton_forward_kinematics(skeleton, pose);
  return pose;
}

SkeletonPose identity_pose(int joint_count) {
  const auto n = static_cast<std::size_t>(joint_count);
  return SkeletonPose{std::vector<Quat>(n, Quat::Identity()), std::vector<Vec3>(n, Vec3::Zero()),
                      std::vector<Quat>(n, Quat::Identity()), std::vector<Vec3>(n, Vec3::Zero())};
}

void skeleton_forward_kinematics(const Skeleton& skeleton, SkeletonPose& pose) {
  const int n = skeleton.joint_count();
  assert(static_cast<int>(pose.local_rotations.size()) == n);
  assert(static_cast<int>(pose.local_translations.size()) == n);
  assert(static_cast<int>(pose.global_rotations.size()) == n);
  assert(static_cast<int>(pose.global_positions.size()) == n);
  const std::vector<int>& parents = skeleton.parents();
  for (int i = 0; i < n; ++i) {
    const int p = parents[i];
    if (p < 0) {
      pose.global_rotations[i] = pose.local_rotations[i];
      pose.global_positions[i] = pose.local_translations[i];
    } else {
      pose.global_rotations[i] = pose.global_rotations[p] * pose.local_rotations[i];
      pose.global_positions[i] =
          pose.global_positions[p] + pose.global_rotations[p] * pose.local_translations[i];
    }
  }
}

}  // namespace animkit
