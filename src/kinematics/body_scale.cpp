#include "animkit/kinematics/body_scale.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace animkit {

double rest_leg_length(const Skeleton& skeleton, const BipedLegs& legs) {
  const SkeletonPose rest = skeleton_rest_pose(skeleton);
  double longest = 0.0;
  for (const LegJoints& leg : legs) {
    const Vec3& hip = rest.global_positions[leg.hip];
    const Vec3& knee = rest.global_positions[leg.knee];
    const Vec3& ankle = rest.global_positions[leg.ankle];
    longest = std::max(longest, (knee - hip).stableNorm() + (ankle - knee).stableNorm());
  }
  return longest;
}

Result<BodyScale> detect_body_scale(const Skeleton& skeleton, const BipedLegs& legs) {
  const double leg = rest_leg_length(skeleton, legs);
  if (!(leg > 0.0) || !std::isfinite(leg)) {
    return fail("cannot tell the units of the skeleton: its legs have no length at rest");
  }
  const LengthUnit* best = nullptr;
  double best_distance = std::numeric_limits<double>::infinity();
  for (const LengthUnit& unit : kBvhLengthUnits) {
    // As a sum of logarithms: a leg of 1e-300 units in millimetres must not underflow to 0.
    const double distance = std::abs(std::log(leg) + std::log(unit.metres / kTypicalLegMetres));
    if (distance < best_distance) {
      best_distance = distance;
      best = &unit;
    }
  }
  const double metres = leg * best->metres;
  if (metres < kMinLegMetres || metres > kMaxLegMetres) {
    std::ostringstream message;
    message.precision(3);
    message << "cannot tell the units of the skeleton: its legs are " << leg
            << " units long, which is no person's leg in metres, centimetres, millimetres, "
               "inches or CMU's unit (nearest: "
            << metres << " m in " << best->name << "; a person's are about " << kTypicalLegMetres
            << " m)";
    return fail(message.str());
  }
  return BodyScale{.unit = *best, .leg_units = leg};
}

}  // namespace animkit
