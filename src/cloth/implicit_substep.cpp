#include "animkit/cloth/implicit_substep.h"

#include <algorithm>

namespace animkit {

GradientStop begin_substep(const IncrementalPotential& potential, double tolerance,
                           double start_norm, StepReport& report) {
  if (report.substeps_done == 0) report.gradient_norm_start = start_norm;
  ++report.substeps_done;
  const GradientStop stop{std::max(tolerance * start_norm, potential.gradient_floor())};
  report.gradient_tolerance = std::max(report.gradient_tolerance, stop.threshold);
  return stop;
}

void end_substep(const ClothModel& model, Eigen::VectorXd& x, double h, ClothState& state) {
  // v_{n+1} = (x_{n+1} - x_n) / h; pinned particles were never unknowns and stay put.
  for (int i = 0; i < model.particle_count(); ++i) {
    if (model.pinned[i]) {
      x.segment<3>(3 * i) = state.positions.segment<3>(3 * i);
      state.velocities.segment<3>(3 * i).setZero();
    } else {
      state.velocities.segment<3>(3 * i) =
          (x.segment<3>(3 * i) - state.positions.segment<3>(3 * i)) / h;
    }
  }
  state.positions.swap(x);
}

}  // namespace animkit
