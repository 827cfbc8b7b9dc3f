#pragma once
// How long a skeleton's units are, told from its body: motion-capture files carry no unit (CMU's
// BVH files use inch / 0.45, others centimetres, metres or inches), and a foot lock run in the
// wrong one finds no foot on the ground. An adult's leg from hip to ankle is about 0.49 of the
// body's height (thigh 0.245 H, shank 0.246 H: D. A. Winter, "Biomechanics and Motor Control of
// Human Movement", 4th ed., Wiley 2009, figure 4.1), about 0.8 m; the unit that makes the
// skeleton's legs nearest that length is taken.
#include <array>
#include <string_view>

#include "animkit/core/result.h"
#include "animkit/kinematics/foot_lock.h"
#include "animkit/kinematics/skeleton.h"

namespace animkit {

/// A length unit a skeleton's file may be in: its name and its size in metres.
struct LengthUnit {
  /// Plural name, as messages print it ("centimetres").
  std::string_view name;
  double metres = 1.0;  ///< metres per unit
};

/// The units a BVH file is taken to be in.
inline constexpr std::array<LengthUnit, 5> kBvhLengthUnits = {
    {{"metres", 1.0},
     {"centimetres", 0.01},
     {"millimetres", 0.001},
     {"inches", 0.0254},
     {"CMU's unit (inch / 0.45)", 0.056444}}};

/// An adult's leg, hip to ankle, in metres (see above), and the range a detected scale must put
/// the legs in.
inline constexpr double kTypicalLegMetres = 0.8;
inline constexpr double kMinLegMetres = 0.4, kMaxLegMetres = 1.3;

/// What detect_body_scale() found: the skeleton's unit and its rest leg length in that unit.
struct BodyScale {
  LengthUnit unit;  ///< the entry of kBvhLengthUnits that puts the legs nearest kTypicalLegMetres
  double leg_units =
      0.0;  ///< hip to knee to ankle at rest, the longer leg, in the skeleton's units
};

/// The skeleton's leg length at rest (hip to knee plus knee to ankle, the longer of the two), in
/// its own units.
double rest_leg_length(const Skeleton& skeleton, const BipedLegs& legs);

/// The unit of kBvhLengthUnits that puts the legs nearest kTypicalLegMetres (by ratio). Errors
/// when even that leaves them outside kMinLegMetres..kMaxLegMetres ("cannot tell the units of
/// the skeleton: its legs are 3 units long, 3 m in metres, 7.6 cm in inches ..."), or for legs
/// of no length.
Result<BodyScale> detect_body_scale(const Skeleton& skeleton, const BipedLegs& legs);

}  // namespace animkit
