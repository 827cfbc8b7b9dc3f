#include "animkit/cloth/local_global.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "animkit/cloth/implicit_substep.h"
#include "animkit/core/validation.h"

namespace animkit {

using Clock = StageClock;

std::optional<Error> LocalGlobalSettings::validate() const {
  if (!std::isfinite(tolerance) || tolerance <= 0.0 || tolerance >= 1.0) {
    return Error{"tolerance must be in (0, 1), got " + format_number(tolerance)};
  }
  if (max_iterations < 1) {
    return Error{"max local/global iterations must be at least 1, got " +
                 std::to_string(max_iterations)};
  }
  if (!std::isfinite(spectral_radius) || spectral_radius <= 0.0 || spectral_radius >= 1.0) {
    return Error{"Chebyshev spectral radius must be in (0, 1), got " +
                 format_number(spectral_radius)};
  }
  if (chebyshev_delay < 0) {
    return Error{"Chebyshev delay must be at least 0, got " + std::to_string(chebyshev_delay)};
  }
  return std::nullopt;
}

LocalGlobal::LocalGlobal(std::shared_ptr<const ClothModel> model,
                         const LocalGlobalSettings& settings)
    : model_owner_(std::move(model)),
      model_(*model_owner_),
      settings_(settings),
      potential_(model_),
      system_(model_),
      x_(3 * model_.particle_count()),
      previous_(3 * model_.particle_count()),
      gradient_(3 * model_.particle_count()),
      direction_(3 * model_.particle_count()),
      step_(3 * model_.particle_count()) {}

void LocalGlobal::step(ClothState& state, double h, StepReport& report,
                       const Eigen::VectorXd* external_forces) {
  const auto substep_start = Clock::now();
  auto t = substep_start;
  if (system_.factorize(h)) report.ms_hessian += ms_since(t);

  t = Clock::now();
  potential_.prepare(state, h, external_forces);
  x_ = potential_.predicted();
  previous_ = x_;
  potential_.gradient(x_, gradient_);
  double gradient_norm = gradient_.norm();
  report.ms_gradient += ms_since(t);

  const GradientStop stop =
      begin_implicit_substep(potential_, gradient_norm, settings_.tolerance, report);
  bool converged = stop.reached(gradient_norm);

  // Wang 2015, eq. 12: x_{k+1} = omega_{k+1} (x^_{k+1} - x_{k-1}) + x_{k-1}, x^_{k+1} the plain
  // iterate from x_k, with omega = 1 for the first `delay` iterations, then
  // omega = 2 / (2 - rho^2), then omega_{k+1} = 4 / (4 - rho^2 omega_k).
  const double rho2 = settings_.spectral_radius * settings_.spectral_radius;
  int chebyshev_start = settings_.chebyshev_delay;  // iteration of the sequence's first omega
  double omega = 1.0;
  for (int k = 0; !converged && std::isfinite(gradient_norm) && k < settings_.max_iterations; ++k) {
    IterationRecord record;
    if (settings_.record_iterations) record.objective = potential_.value(x_);

    // Local and global step together: the plain direction -P^-1 grad g(x_k).
    t = Clock::now();
    direction_ = -gradient_;
    system_.solve_in_place(direction_);
    report.ms_linear_solve += ms_since(t);

    t = Clock::now();
    const bool accelerate = settings_.chebyshev && k >= chebyshev_start;
    omega = !accelerate            ? 1.0
            : k == chebyshev_start ? 2.0 / (2.0 - rho2)
                                   : 4.0 / (4.0 - rho2 * omega);
    if (accelerate) {
      // x_{k+1} - x_k = omega (x_k + d - x_{k-1}) + x_{k-1} - x_k.
      step_ = omega * direction_ + (omega - 1.0) * (x_ - previous_);
    } else {
      step_ = direction_;
    }
    double slope = gradient_.dot(step_);
    const bool check = accelerate && settings_.monotone;
    double decrease = check || settings_.record_iterations ? potential_.difference(x_, step_) : 0.0;
    if (check && !(decrease <= 0.0 && slope < 0.0)) {
      // The accelerated iterate went uphill: take the plain step, which cannot, and start
      // the Chebyshev sequence afresh from there.
      step_ = direction_;
      omega = 1.0;
      chebyshev_start = k + 1;
      slope = gradient_.dot(step_);
      if (settings_.record_iterations) decrease = potential_.difference(x_, step_);
    }
    report.ms_line_search += ms_since(t);

    previous_ = x_;
    x_ += step_;
    t = Clock::now();
    potential_.gradient(x_, gradient_);
    gradient_norm = gradient_.norm();
    report.ms_gradient += ms_since(t);
    ++report.newton_iterations;
    converged = stop.reached(gradient_norm);

    if (settings_.record_iterations) {
      record.gradient_norm = gradient_norm;
      record.ms = ms_since(substep_start);
      record.objective_after = potential_.value(x_);
      record.decrease = decrease;
      record.slope = slope;
      record.alpha = omega;  // the Chebyshev weight (1: a plain step)
      report.iterations.push_back(record);
    }
  }
  report.gradient_norm_end = gradient_norm;
  report.converged = report.converged && converged;

  finish_implicit_substep(model_, x_, h, state);
}

}  // namespace animkit
