#include "lab_float_ik.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace animkit::bench {

using Eigen::Quaternionf;
using Eigen::Vector3f;

LabFloatArm LabFloatArm::rest() {
  const Vector3f init[] = {
      {0.f, 1.7f, 0.f}, {0.f, 0.9f, 0.f}, {0.f, 0.5f, 0.f}, {0.f, 0.3f, 0.f}, {0.f, -0.9f, 0.f}};
  LabFloatArm arm;
  for (int i = 0; i < 5; ++i) {
    arm.local_rotation.push_back(Quaternionf::Identity());
    arm.global_rotation.push_back(Quaternionf::Identity());
    arm.global_position.push_back(init[i]);
    arm.local_offset.push_back(i == 0 ? init[0] : Vector3f(init[i] - init[i - 1]));
    arm.offset_length.push_back(i == 0 ? 0.f : arm.local_offset.back().norm());
  }
  return arm;
}

Quaternionf glm_rotation(const Vector3f& orig, const Vector3f& dest) {
  const float eps = std::numeric_limits<float>::epsilon();
  const float cos_theta = orig.dot(dest);
  if (cos_theta >= 1.f - eps) return Quaternionf::Identity();  // the cut-off that stalls CCD
  if (cos_theta < -1.f + eps) {
    Vector3f axis = Vector3f::UnitZ().cross(orig);
    if (axis.squaredNorm() < eps) axis = Vector3f::UnitX().cross(orig);
    return Quaternionf(Eigen::AngleAxisf(std::numbers::pi_v<float>, axis.normalized()));
  }
  const Vector3f axis = orig.cross(dest);
  const float s = std::sqrt((1.f + cos_theta) * 2.f);
  const float invs = 1.f / s;
  return Quaternionf(s * 0.5f, axis.x() * invs, axis.y() * invs, axis.z() * invs);
}

void lab_forward_kinematics(LabFloatArm& arm, int start) {
  if (start == 0) {
    arm.global_rotation[0] = arm.local_rotation[0];
    arm.global_position[0] = arm.local_offset[0];
    start = 1;
  }
  for (std::size_t i = static_cast<std::size_t>(start); i < arm.local_offset.size(); ++i) {
    arm.global_rotation[i] = arm.global_rotation[i - 1] * arm.local_rotation[i];
    arm.global_position[i] =
        arm.global_position[i - 1] + arm.global_rotation[i - 1] * arm.local_offset[i];
  }
}

int lab_ccd(LabFloatArm& arm, const Vector3f& target, int max_iterations, float eps) {
  lab_forward_kinematics(arm, 0);
  const int n = static_cast<int>(arm.local_offset.size());
  int iteration = 0;
  for (; iteration < max_iterations && (arm.end_effector() - target).norm() > eps; ++iteration) {
    for (int i = n - 2; i >= 0; --i) {
      const Vector3f a = (arm.end_effector() - arm.global_position[i]).normalized();
      const Vector3f b = (target - arm.global_position[i]).normalized();
      const Quaternionf global = glm_rotation(a, b) * arm.global_rotation[i];
      arm.local_rotation[i] = i == 0 ? global : arm.global_rotation[i - 1].inverse() * global;
      lab_forward_kinematics(arm, i);
    }
  }
  return iteration;
}

int lab_fabrik(LabFloatArm& arm, const Vector3f& target, int max_iterations, float eps) {
  lab_forward_kinematics(arm, 0);
  const int n = static_cast<int>(arm.local_offset.size());
  std::vector<Vector3f> backward(n), forward(n);
  int iteration = 0;
  for (; iteration < max_iterations && (arm.end_effector() - target).norm() > eps; ++iteration) {
    backward[n - 1] = target;
    for (int i = n - 2; i >= 0; --i) {
      backward[i] = backward[i + 1] + arm.offset_length[i + 1] *
                                          (arm.global_position[i] - backward[i + 1]).normalized();
    }
    forward[0] = arm.global_position[0];
    for (int i = 0; i < n - 1; ++i) {
      forward[i + 1] =
          forward[i] + arm.offset_length[i + 1] * (backward[i + 1] - forward[i]).normalized();
    }
    arm.global_position = forward;
  }
  for (int i = 0; i < n - 1; ++i) {
    arm.global_rotation[i] =
        glm_rotation(arm.local_offset[i + 1].normalized(),
                     (arm.global_position[i + 1] - arm.global_position[i]).normalized());
  }
  arm.local_rotation[0] = arm.global_rotation[0];
  for (int i = 1; i < n - 1; ++i) {
    arm.local_rotation[i] = arm.global_rotation[i - 1].inverse() * arm.global_rotation[i];
  }
  lab_forward_kinematics(arm, 0);
  return iteration;
}

}  // namespace animkit::bench
