#include "animkit/collision/ccd.h"

#include <algorithm>
#include <cmath>

#include "animkit/collision/distance_type.h"
#include "animkit/core/validation.h"

namespace animkit {

std::optional<Error> AdditiveCcdSettings::validate() const {
  if (!(separation_fraction > 0.0 && separation_fraction < 1.0)) {
    return Error{"CCD separation fraction must be in (0, 1), got " +
                 format_number(separation_fraction)};
  }
  if (!(std::isfinite(thickness) && thickness >= 0.0)) {
    return Error{"CCD thickness must be finite and >= 0, got " + format_number(thickness)};
  }
  if (!(max_time > 0.0 && max_time <= 1.0)) {
    return Error{"CCD max time must be in (0, 1], got " + format_number(max_time)};
  }
  if (max_iterations < 1) {
    return Error{"CCD max iterations must be >= 1, got " + std::to_string(max_iterations)};
  }
  return std::nullopt;
}

namespace {

// Additive CCD (C-IPC, Algorithm 1) for N vertices, the first `first_count` of which form one
// primitive. `distance_squared` maps the N current positions to the squared distance.
template <int N, class DistanceSquared>
Result<CcdResult> additive_ccd(const std::array<Vec3, N>& start, const std::array<Vec3, N>& end,
                               int first_count, const AdditiveCcdSettings& settings,
                               DistanceSquared&& distance_squared) {
  if (auto error = settings.validate()) return std::unexpected(*error);
  for (int i = 0; i < N; ++i) {
    if (!is_finite(start[i]) || !is_finite(end[i])) {
      return fail("CCD vertex " + std::to_string(i) + " has a non-finite coordinate");
    }
  }
  // Displacements without their mean, and the bound l_p on the relative speed of any two
  // points of the two primitives.
  std::array<Vec3, N> motion;
  Vec3 mean = Vec3::Zero();
  for (int i = 0; i < N; ++i) {
    motion[i] = end[i] - start[i];
    mean += motion[i];
  }
  mean /= N;
  double first_max = 0.0, second_max = 0.0;
  for (int i = 0; i < N; ++i) {
    motion[i] -= mean;
    double& side_max = i < first_count ? first_max : second_max;
    side_max = std::max(side_max, motion[i].norm());
  }
  const double speed_bound = first_max + second_max;  // l_p

  const double xi = settings.thickness, s = settings.separation_fraction;
  // d - xi as (d^2 - xi^2) / (d + xi): no cancellation between d and xi for thick primitives.
  const auto gap_at = [&](double t, int& iterations) {
    std::array<Vec3, N> x;
    for (int i = 0; i < N; ++i) x[i] = start[i] + t * motion[i];
    ++iterations;
    const double d2 = distance_squared(x);
    const double d = std::sqrt(d2);
    return d + xi > 0.0 ? (d2 - xi * xi) / (d + xi) : 0.0;
  };

  CcdResult result;
  const double gap0 = gap_at(0.0, result.iterations);
  if (gap0 <= 0.0) {  // already touching (or within the thickness): no motion is safe
    result.time_of_impact = 0.0;
    result.collides = true;
    return result;
  }
  if (speed_bound == 0.0) {  // a common translation only: the distance never changes
    result.time_of_impact = settings.max_time;
    return result;
  }
  const double target = s * gap0;  // g
  double t = 0.0;
  double step = (1.0 - s) * gap0 / speed_bound;
  while (true) {
    const double next = std::min(t + step, settings.max_time);
    if (next <= t) break;  // no representable progress: stop at t (safe)
    const double gap = gap_at(next, result.iterations);
    // The first step is safe by the Lipschitz bound alone (C-IPC accepts it unmeasured); it is
    // refused only if rounding left no gap at all.
    if (gap < target && (t > 0.0 || gap <= 0.0)) break;
    t = next;
    if (t >= settings.max_time) {
      result.time_of_impact = settings.max_time;
      return result;
    }
    if (result.iterations >= settings.max_iterations) break;
    step = 0.9 * gap / speed_bound;
  }
  result.time_of_impact = t;
  result.collides = true;
  return result;
}

}  // namespace

Result<CcdResult> point_triangle_ccd(const std::array<Vec3, 4>& start,
                                     const std::array<Vec3, 4>& end,
                                     const AdditiveCcdSettings& settings) {
  return additive_ccd<4>(start, end, 1, settings, [](const std::array<Vec3, 4>& x) {
    return point_triangle_distance_squared(x[0], x[1], x[2], x[3]);
  });
}

Result<CcdResult> edge_edge_ccd(const std::array<Vec3, 4>& start, const std::array<Vec3, 4>& end,
                                const AdditiveCcdSettings& settings) {
  return additive_ccd<4>(start, end, 2, settings, [](const std::array<Vec3, 4>& x) {
    return edge_edge_distance_squared(x[0], x[1], x[2], x[3]);
  });
}

Result<CcdResult> point_edge_ccd(const std::array<Vec3, 3>& start, const std::array<Vec3, 3>& end,
                                 const AdditiveCcdSettings& settings) {
  return additive_ccd<3>(start, end, 1, settings, [](const std::array<Vec3, 3>& x) {
    return point_edge_distance_squared(x[0], x[1], x[2]);
  });
}

Result<CcdResult> point_point_ccd(const std::array<Vec3, 2>& start, const std::array<Vec3, 2>& end,
                                  const AdditiveCcdSettings& settings) {
  return additive_ccd<2>(start, end, 1, settings, [](const std::array<Vec3, 2>& x) {
    return point_point_distance_squared(x[0], x[1]);
  });
}

}  // namespace animkit
