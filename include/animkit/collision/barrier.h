#pragma once
// IPC's log barrier on squared distances (Li et al., SIGGRAPH 2020, eq. 6, written for squared
// distances as IPC's implementation evaluates it, so no square root enters the derivatives):
//   b(d) = -(d - dhat)^2 ln(d / dhat)   for 0 < d < dhat,   0 for d >= dhat,
// with d the squared distance between two primitives and dhat the squared activation distance.
// b > 0 inside, b -> infinity as d -> 0, and b, b' and b'' all vanish at d = dhat (b is C^2
// there: b'(dhat) = 0 and b''(dhat) = 0 from the (d - dhat)^2 factor).
//   b'(d)  = -2 (d - dhat) ln(d / dhat) - (d - dhat)^2 / d
//   b''(d) = -2 ln(d / dhat) - 4 (d - dhat) / d + (d - dhat)^2 / d^2
// b is convex in d on (0, dhat) (b'' > 0 there); the barrier of a pair, b(d(x)), is not convex
// in the positions, so Newton projects its Hessian (psd_projection.h).
// The contact stiffness kappa that multiplies b is the caller's.
#include <cassert>
#include <cmath>

#include "animkit/core/result.h"
#include "animkit/core/validation.h"

namespace animkit {

/// IPC's log barrier b(d) on a squared distance d with squared activation distance dhat, and its
/// first and second derivatives in d (formulas in the comment at the top of this header).
class LogBarrier {
 public:
  /// dhat: the squared activation distance (squared position units), finite and > 0.
  /// Fails with "barrier dhat must be a positive finite squared distance, got <dhat>".
  static Result<LogBarrier> create(double dhat) {
    if (!(std::isfinite(dhat) && dhat > 0.0)) {
      return fail("barrier dhat must be a positive finite squared distance, got " +
                  format_number(dhat));
    }
    return LogBarrier(dhat);
  }

  /// The squared activation distance (squared position units): b, b' and b'' are 0 for d >= dhat.
  double dhat() const { return dhat_; }

  /// b(d) for a squared distance d > 0 (the barrier is infinite at contact; CCD keeps d > 0).
  double value(double d) const {
    assert(d > 0.0 && "the barrier needs a positive distance");
    if (d >= dhat_) return 0.0;
    const double gap = d - dhat_;
    return -gap * gap * std::log(d / dhat_);
  }

  /// b'(d), d > 0; <= 0 (the barrier pushes apart).
  double first_derivative(double d) const {
    assert(d > 0.0 && "the barrier needs a positive distance");
    if (d >= dhat_) return 0.0;
    const double gap = d - dhat_;
    return -2.0 * gap * std::log(d / dhat_) - gap * gap / d;
  }

  /// b''(d), d > 0; >= 0.
  double second_derivative(double d) const {
    assert(d > 0.0 && "the barrier needs a positive distance");
    if (d >= dhat_) return 0.0;
    const double gap = d - dhat_;
    const double ratio = gap / d;
    return -2.0 * std::log(d / dhat_) - 4.0 * ratio + ratio * ratio;
  }

 private:
  explicit LogBarrier(double dhat) : dhat_(dhat) {}
  double dhat_ = 1.0;
};

}  // namespace animkit
