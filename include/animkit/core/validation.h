#pragma once
// Helpers for validating user input at the API boundary.
#include <cmath>
#include <sstream>
#include <string>

#include "animkit/core/types.h"

namespace animkit {

inline bool is_finite(const Vec3& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

inline bool is_finite(const Quat& q) {
  return std::isfinite(q.w()) && std::isfinite(q.x()) && std::isfinite(q.y()) &&
         std::isfinite(q.z());
}

/// "(0, 1.7, 0)": a vector as users write it, for error messages.
inline std::string to_string(const Vec3& v) {
  std::ostringstream s;
  s << '(' << v.x() << ", " << v.y() << ", " << v.z() << ')';
  return s.str();
}

}  // namespace animkit
