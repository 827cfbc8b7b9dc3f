#pragma once
// Options and result shared by every IK solver, so callers switch solvers with an enum.
#include <optional>

#include "animkit/core/result.h"

namespace animkit {

/// Options of one IK solve. The defaults are the lab's (100 iterations, eps = 1e-4).
struct IkOptions {
  int max_iterations = 100;  ///< cap on full solver iterations; >= 1
  double tolerance = 1e-4;   ///< converged when |end effector - target| <= tolerance; > 0

  std::optional<Error> validate() const;
};

/// What one IK solve did.
struct IkResult {
  int iterations = 0;      ///< full iterations run (a CCD sweep, a FABRIK backward+forward pass)
  double error = 0.0;      ///< |end effector - target| after the solve (scene units)
  bool converged = false;  ///< error <= tolerance
  /// False when no pose reaches the target: it is farther from the root than the chain's reach
  /// (the chain then points straight at it) or nearer than its minimum reach.
  bool reachable = true;
};

}  // namespace animkit
