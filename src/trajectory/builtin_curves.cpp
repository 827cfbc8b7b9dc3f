#include "animkit/trajectory/builtin_curves.h"

#include <cmath>
#include <numbers>

namespace animkit {

std::vector<Vec3> uneven_spiral_targets() {
  constexpr int kSteps = 300;
  std::vector<Vec3> out;
  out.reserve(kSteps + 1);
  for (int i = 0; i <= kSteps; ++i) {
    const double t = std::pow(static_cast<double>(i) / kSteps, 3.0);
    const double angle = 6.0 * std::numbers::pi * t, radius = 0.1 + 0.5 * t;
    out.emplace_back(radius * std::cos(angle), 0.0, radius * std::sin(angle));
  }
  return out;
}

}  // namespace animkit
