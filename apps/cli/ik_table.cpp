#include "ik_table.h"

#include <cstdio>

namespace animkit::cli {

void print_ik_table_header() {
  std::printf("%-12s %-7s %7s %10s %11s %9s %8s %10s %13s %11s\n", "shape", "solver", "targets",
              "converged", "unreachable", "iter mean", "iter max", "error max", "max step rad",
              "us/target");
}

void print_ik_table_row(std::string_view shape, std::string_view solver, const DrawingSummary& s) {
  std::printf("%-12.*s %-7.*s %7d %9.1f%% %11d %9.2f %8d %10.2e %13.4f %11.2f\n",
              static_cast<int>(shape.size()), shape.data(), static_cast<int>(solver.size()),
              solver.data(), s.targets, 100.0 * s.converged_fraction, s.unreachable_targets,
              s.iterations_mean, s.iterations_max, s.error_max, s.max_joint_step_rad,
              s.solve_time_us_median);
}

}  // namespace animkit::cli
