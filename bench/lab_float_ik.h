#pragma once
// The lab's straightforward approach, kept as the benchmark baseline: float vectors and
// quaternions, glm::rotation's shortest arc (with its "close to identity" cut-off at float
// epsilon), FK re-run after every joint, and FABRIK with buffers allocated on every call.
// Same chain and targets as animkit's solvers, so the two can be timed in one binary.
#include <Eigen/Geometry>
#include <span>
#include <vector>

#include "animkit/core/types.h"

namespace animkit::bench {

struct LabFloatArm {
  std::vector<Eigen::Vector3f> local_offset;
  std::vector<float> offset_length;
  std::vector<Eigen::Vector3f> global_position;
  std::vector<Eigen::Quaternionf> local_rotation;
  std::vector<Eigen::Quaternionf> global_rotation;

  /// The lab's arm at rest.
  static LabFloatArm rest();
  const Eigen::Vector3f& end_effector() const { return global_position.back(); }
};

/// glm::rotation(orig, dest) for unit vectors, in float, as glm implements it.
Eigen::Quaternionf glm_rotation(const Eigen::Vector3f& orig, const Eigen::Vector3f& dest);

void lab_forward_kinematics(LabFloatArm& arm, int start);
/// The lab's CCD; returns the iterations used.
int lab_ccd(LabFloatArm& arm, const Eigen::Vector3f& target, int max_iterations, float eps);
/// The lab's FABRIK; returns the iterations used.
int lab_fabrik(LabFloatArm& arm, const Eigen::Vector3f& target, int max_iterations, float eps);

}  // namespace animkit::bench
