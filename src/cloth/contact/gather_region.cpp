#include "gather_region.h"

#include <algorithm>
#include <cmath>

namespace animkit {

bool GatherRegion::inside(double coordinate, Eigen::Index k) const {
  // The quiet comparisons: a NaN is outside, and raises no floating-point exception.
  return std::isgreaterequal(coordinate, lower_[k]) &&
         std::islessequal(coordinate, lower_[k] + extent_[k]);
}

void GatherRegion::set(const Eigen::VectorXd& x, const Eigen::VectorXd* step, double min_reach,
                       const Eigen::VectorXd& obstacle_positions) {
  const Eigen::Index n = x.size();
  lower_.resize(n);
  extent_.resize(n);
  reach_.setZero(n / 3);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double ahead = step ? kMargin * (*step)[k] : 0.0;
    lower_[k] = std::min(x[k], x[k] + ahead) - min_reach;
    extent_[k] = std::abs(ahead) + 2.0 * min_reach;
    const double farthest = std::abs(ahead) + min_reach;
    reach_[k / 3] += farthest * farthest;
  }
  reach_ = reach_.cwiseSqrt();
  obstacles_ = obstacle_positions;
  valid_ = true;
}

bool GatherRegion::covers(const Eigen::VectorXd& x,
                          const Eigen::VectorXd& obstacle_positions) const {
  if (!valid_ || x.size() != lower_.size() || obstacle_positions.size() != obstacles_.size())
    return false;
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    if (!inside(x[k], k)) return false;
  }
  return obstacle_positions == obstacles_;
}

bool GatherRegion::covers_step(const Eigen::VectorXd& x, const Eigen::VectorXd& step) const {
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    if (!inside(x[k] + step[k], k)) return false;
  }
  return true;
}

}  // namespace animkit
