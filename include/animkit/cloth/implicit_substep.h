#pragma once
// The stages every implicit integrator shares around its own minimization of g: the stopping
// test (docs/implicit-step.md, the same for every solver so their results compare one to one) and
// the velocity update. Newton, VBD and any later solver call these instead of repeating them.
#include <Eigen/Core>
#include <chrono>
#include <cmath>

#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/incremental_potential.h"
#include "animkit/cloth/step_report.h"

namespace animkit {

/// The clock the stages are timed with (StepReport's ms fields).
using StageClock = std::chrono::steady_clock;
/// Milliseconds since `start`.
inline double ms_since(StageClock::time_point start) {
  return std::chrono::duration<double, std::milli>(StageClock::now() - start).count();
}

/// |grad g(x)| <= max(tolerance |grad g(y)|, the potential's rounding floor).
struct GradientStop {
  double stop = 0.0;  ///< the |grad g| at or below which the minimization has converged
  /// Written so that a NaN or an infinite norm never counts as converged (inf <= inf is true).
  bool reached(double norm) const { return std::isfinite(norm) && norm <= stop; }
};

/// The diagonal of the bounding box of stacked positions (x0 y0 z0 x1 ...): the scene size
/// that NewtonSettings::velocity_tolerance is a fraction of. 0 for fewer than two points.
double bounding_diagonal(const Eigen::VectorXd& positions);

/// Starts a substep's report: |grad g(y)| (`start_norm`) as the step's start on its first
/// substep, one more substep done, the tolerance reached so far; returns the stopping test.
GradientStop begin_implicit_substep(const IncrementalPotential& potential, double start_norm,
                                    double tolerance, StepReport& report);

/// v_{n+1} = (x_{n+1} - x_n) / h, then x_{n+1} copied into `state`
/// (its buffers stay put: views of them stay valid). Pinned particles
/// were never unknowns: they stay at x_n with zero velocity.
void finish_implicit_substep(const ClothModel& model, Eigen::VectorXd& x, double h,
                             ClothState& state);

}  // namespace animkit
