#pragma once
// The straightforward implicit Euler, kept as the benchmark baseline: float, the same
// objective g (inertia, springs, dashpots) and the same Newton + Armijo loop as animkit, but
// with the Hessian rebuilt from triplets and a fresh Eigen::SimplicialLLT (symbolic analysis
// and numeric factorization) at every Newton iteration, and the projected Hessian always.
#include <Eigen/Core>
#include <vector>

#include "animkit/cloth/cloth_model.h"

namespace animkit::bench {

class LabFloatImplicitEuler {
 public:
  explicit LabFloatImplicitEuler(const ClothModel& model);

  /// One step of h from (x, v) in place. Returns the Newton iterations used.
  int step(Eigen::VectorXf& x, Eigen::VectorXf& v, float h, float tolerance, int max_iterations);

 private:
  float objective(const Eigen::VectorXf& x) const;
  void gradient(const Eigen::VectorXf& x, Eigen::VectorXf& g) const;

  const ClothModel& model_;
  float h_ = 0.0f;
  Eigen::VectorXf y_, x_start_;
  std::vector<Eigen::Vector3f> axis_;
};

}  // namespace animkit::bench
