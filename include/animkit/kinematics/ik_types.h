#pragma once
// Options and result shared by every IK solver, so callers switch solvers with an enum.
#include <optional>

#include "animkit/core/result.h"

namespace animkit {

/// How FABRIK turns the joint positions it found back into joint rotations.
enum class FabrikRotations {
  /// The lab's way: each joint's world rotation is the shortest arc from its rest bone
  /// direction to its new one. A function of the positions alone, but where a bone points
  /// nearly opposite to its rest direction the arc's axis swings fast, so the joint twists
  /// visibly between frames (the jitter of the lab's question 3).
  from_rest,
  /// Each joint's world rotation is its previous one turned by the shortest arc from its
  /// previous bone direction to its new one: the smallest change that fits, so no twist jumps.
  from_previous,
};

/// Largest target coordinate a solve accepts (scene units, world space). Far beyond any reach,
/// and small enough that squared distances (up to 3e18) neither overflow nor lose the chain's
/// bone lengths entirely to rounding; a target beyond it is refused, not solved wrong.
constexpr double kMaxTargetCoordinate = 1e9;

/// Options of one IK solve. The defaults are the lab's (100 iterations, eps = 1e-4).
struct IkOptions {
  int max_iterations = 100;  ///< cap on full solver iterations; >= 1
  double tolerance = 1e-4;   ///< converged when |end effector - target| <= tolerance; > 0
  FabrikRotations fabrik_rotations = FabrikRotations::from_rest;  ///< FABRIK only; CCD ignores it

  /// The first problem (max_iterations < 1, a non-positive or non-finite tolerance), or nothing.
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
