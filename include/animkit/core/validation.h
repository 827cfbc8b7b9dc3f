#pragma once
// Helpers for validating user input at the API boundary.
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "animkit/core/types.h"

namespace animkit {

/// How far |q| of a rotation, or the length of an axis, may stray from 1 before the input is
/// refused as not unit: far above the rounding of a normalized quaternion written with 9 digits,
/// far below a user's mistake.
inline constexpr double kUnitTolerance = 1e-6;

/// Bones shorter than this are treated as zero length: their direction is undefined.
inline constexpr double kMinBoneLength = 1e-9;

/// Every coordinate of `v` finite (no NaN or infinity).
inline bool is_finite(const Vec3& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

/// Every component of `q` (w, x, y, z) finite (no NaN or infinity).
inline bool is_finite(const Quat& q) {
  return std::isfinite(q.w()) && std::isfinite(q.x()) && std::isfinite(q.y()) &&
         std::isfinite(q.z());
}

/// Every entry finite. Unlike Eigen's allFinite() (which computes x - x), never raises a
/// floating-point exception on inf, so it is safe under the tests' FP traps.
inline bool all_finite(const Eigen::VectorXd& v) {
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i])) return false;
  }
  return true;
}

/// A number as users write it, for error messages: "1e-09", "0.2", "nan" (%g, unlike
/// std::to_string, which prints 1e-9 as "0.000000").
inline std::string format_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

/// "(0, 1.7, 0)": a vector as users write it, for error messages.
inline std::string to_string(const Vec3& v) {
  std::ostringstream s;
  s << '(' << v.x() << ", " << v.y() << ", " << v.z() << ')';
  return s.str();
}

/// A closed interval of accepted values. Values beyond a range are refused up front, naming it:
/// the solvers multiply positions, speeds and coefficients together, and past these bounds a
/// step computes infinities (a collider thrown at 1e300 m/s wrote `inf` into its cache).
struct ParameterRange {
  /// Lowest accepted value (included).
  double min, max;  ///< highest accepted value (included)

  /// True when `value` is finite and min <= value <= max.
  bool contains(double value) const { return std::isfinite(value) && value >= min && value <= max; }
  /// True when each coordinate of `v` is finite and within [min, max].
  bool contains(const Vec3& v) const {
    return contains(v.x()) && contains(v.y()) && contains(v.z());
  }
  /// "<what> must be between <min> and <max>, got <value>".
  std::string refusal(const std::string& what, double value) const {
    return what + " must be between " + format_number(min) + " and " + format_number(max) +
           ", got " + format_number(value);
  }
  /// "<what> must have each coordinate between <min> and <max>, got (x, y, z)".
  std::string refusal(const std::string& what, const Vec3& v) const {
    return what + " must have each coordinate between " + format_number(min) + " and " +
           format_number(max) + ", got " + to_string(v);
  }
};

/// The ranges every physical input shares; they span far more than any scene (a 2,000 km
/// world, a bullet's speed a thousand times over) while keeping squares and products finite.
inline constexpr ParameterRange kCoordinateRange{-1e6, 1e6};    ///< positions, m
inline constexpr ParameterRange kSpeedRange{-1e6, 1e6};         ///< velocity components, m/s
inline constexpr ParameterRange kAngularSpeedRange{-1e6, 1e6};  ///< rad/s, per axis
inline constexpr ParameterRange kTimeRange{-1e6, 1e6};          ///< keyframe times, s
/// Coulomb coefficients: real pairs stay below about 2 (rubber on rubber); past 10 the lagged
/// friction forces would swamp every other force of a step.
inline constexpr ParameterRange kFrictionRange{0.0, 10.0};

}  // namespace animkit
