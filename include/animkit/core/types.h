#pragma once
// The small shared vocabulary of animkit: double-precision Eigen vectors and quaternions.
// Solvers use double: a float CCD stalls on the lab's own targets (docs/lab-questions.md).
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace animkit {

using Vec3 = Eigen::Vector3d;
using Quat = Eigen::Quaterniond;

}  // namespace animkit
