#include "animkit/cloth/implicit_substep.h"

#include <algorithm>

namespace animkit {

double bounding_diagonal(const Eigen::VectorXd& positions) {
  const auto points = positions.reshaped(3, positions.size() / 3);
  if (points.cols() == 0) return 0.0;
  return (points.rowwise().maxCoeff() - points.rowwise().minCoeff()).norm();
}

GradientStop begin_implicit_substep(const IncrementalPotential& potential, double start_norm,
                                    double tolerance, StepReport& report) {
  if (report.substeps_done == 0) report.gradient_norm_start = start_norm;
  ++report.substeps_done;
  const GradientStop test{std::max(tolerance * start_norm, potential.gradient_floor())};
  report.gradient_tolerance = std::max(report.gradient_tolerance, test.stop);
  return test;
}

void finish_implicit_substep(const ClothModel& model, Eigen::VectorXd& x, double h,
                             ClothState& state) {
  for (int i = 0; i < model.particle_count(); ++i) {
    if (model.pinned[static_cast<std::size_t>(i)]) {
      x.segment<3>(3 * i) = state.positions.segment<3>(3 * i);
      state.velocities.segment<3>(3 * i).setZero();
    } else {
      state.velocities.segment<3>(3 * i) =
          (x.segment<3>(3 * i) - state.positions.segment<3>(3 * i)) / h;
    }
  }
  // Copied, not swapped: the state's buffers stay where they are for the whole run, so views
  // of them (the Python module's positions array) never dangle.
  state.positions = x;
}

}  // namespace animkit
