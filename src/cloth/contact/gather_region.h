#pragma once
// Where a gathered set of contact pairs stays complete, so that Newton's iterates can reuse it
// instead of running the broad phase twice per iteration (once for the pairs at x, once for the
// pairs along the step).
//
// The pairs are gathered for a box per particle and axis (the broad phase sees each primitive
// swept over its particles' boxes, inflated by the contact distance). Any configuration that
// keeps every particle in its box, with the obstacles where they were, then has every pair
// within the contact distance in the set; and since the boxes are convex, so does every point
// of a step between two such configurations, which is what continuous collision detection over
// the set needs to be exact. Pairs of the set that are farther than the contact distance
// contribute nothing to the barrier's value, gradient and Hessian, so the energy is the same
// function as with the pairs gathered at x alone.
//
// The box runs from x along the step, kMargin times its length, widened by a floor on every
// side: resting cloth under gravity moves a little down and back up every substep and keeps its
// set for many of them; Newton's iterates mostly go on along their first step, or back.
#include <Eigen/Core>

namespace animkit {

class GatherRegion {
 public:
  /// The boxes: per coordinate from x to x + kMargin step (step == nullptr: x alone), widened
  /// by min_reach on both sides, for obstacles at `obstacle_positions`. lower() and extent()
  /// are what the broad phase's swept boxes take (start and step).
  void set(const Eigen::VectorXd& x, const Eigen::VectorXd* step, double min_reach,
           const Eigen::VectorXd& obstacle_positions);
  const Eigen::VectorXd& lower() const { return lower_; }
  const Eigen::VectorXd& extent() const { return extent_; }
  /// How far particle i can get from its position at set() without leaving its box: the
  /// distance to the box's farthest corner. A pair of primitives whose distance at set()'s x
  /// exceeds dhat plus its two primitives' reaches (the largest of their particles'; 0 for
  /// obstacles) stays beyond dhat anywhere in the region: a point of a primitive is a convex
  /// combination of its vertices, so it moves no farther than the farthest of them.
  double reach(int i) const { return reach_[i]; }

  /// Forget the boxes: the next question gathers again.
  void clear() { valid_ = false; }

  /// True when every particle of x is in its box and the obstacles are where they were.
  bool covers(const Eigen::VectorXd& x, const Eigen::VectorXd& obstacle_positions) const;
  /// For x that covers() holds for: true when x + step keeps every particle in its box too.
  bool covers_step(const Eigen::VectorXd& x, const Eigen::VectorXd& step) const;

  /// How far past the step that set it a box reaches: the next iterations' steps are mostly
  /// shorter, so they stay inside.
  static constexpr double kMargin = 1.5;
  /// The floor (min_reach) the contact term gives its boxes, as a fraction of the contact
  /// thickness: Newton's corrections on resting cloth are far shorter. A floor of the whole
  /// thickness, to keep the set of cloth sliding on a surface across steps, gathered larger
  /// sets and was slower (drape-sphere 41 x 41: median step 820 ms against 770 ms).
  static constexpr double kFloorFraction = 0.25;

 private:
  bool inside(double coordinate, Eigen::Index k) const;

  bool valid_ = false;
  Eigen::VectorXd lower_, extent_;  // per coordinate: the box is [lower, lower + extent]
  Eigen::VectorXd reach_;           // per particle
  Eigen::VectorXd obstacles_;       // the obstacles' positions at the gather
};

}  // namespace animkit
