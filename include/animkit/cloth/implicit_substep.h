#pragma once
// What every implicit integrator does around its own iterations, kept in one place so they all
// stop on the same test and end a substep the same way (SPEC.md section 4). ImplicitEuler still
// has its own copy of this (implicit_euler.cpp); it can move to these helpers.
#include <Eigen/Core>
#include <chrono>
#include <cmath>

#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/incremental_potential.h"
#include "animkit/cloth/step_report.h"

namespace animkit {

using SubstepClock = std::chrono::steady_clock;

inline double ms_since(SubstepClock::time_point start) {
  return std::chrono::duration<double, std::milli>(SubstepClock::now() - start).count();
}

/// The stopping test |grad g| <= max(tolerance |grad g(y)|, the rounding floor).
struct GradientStop {
  double threshold = 0.0;
  /// Written so that a NaN or an infinite norm never counts as reached (inf <= inf is true).
  bool reached(double norm) const { return std::isfinite(norm) && norm <= threshold; }
};

/// Starts a substep's report from |grad g(y)| = `start_norm` (the first substep's is the
/// step's start) and returns the stopping test.
GradientStop begin_substep(const IncrementalPotential& potential, double tolerance,
                           double start_norm, StepReport& report);

/// Ends a substep at the solution x (overwritten): v = (x - x_n) / h, pinned particles stay put
/// with v = 0, and `state` takes x.
void end_substep(const ClothModel& model, Eigen::VectorXd& x, double h, ClothState& state);

}  // namespace animkit
