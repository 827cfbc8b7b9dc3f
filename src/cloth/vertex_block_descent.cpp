#include "animkit/cloth/vertex_block_descent.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <string>

#include "../core/parallel.h"
#include "animkit/cloth/bend_energy.h"
#include "animkit/cloth/implicit_substep.h"
#include "animkit/cloth/spring_energy.h"
#include "animkit/core/validation.h"
#include "stacked_vectors.h"

namespace animkit {

std::optional<Error> VbdSettings::validate() const {
  if (!std::isfinite(tolerance) || tolerance <= 0.0 || tolerance >= 1.0) {
    return Error{"tolerance must be in (0, 1), got " + format_number(tolerance)};
  }
  if (max_iterations < 1) {
    return Error{"max VBD iterations must be at least 1, got " + std::to_string(max_iterations)};
  }
  if (check_interval < 1) {
    return Error{"VBD check interval must be at least 1, got " + std::to_string(check_interval)};
  }
  if (!std::isfinite(chebyshev_rho) || chebyshev_rho < 0.0 || chebyshev_rho >= 1.0) {
    return Error{"Chebyshev rho must be in [0, 1), got " + format_number(chebyshev_rho)};
  }
  if (!std::isfinite(gamma) || gamma <= 0.0 || gamma >= 1.0) {
    return Error{"local Armijo gamma must be in (0, 1), got " + format_number(gamma)};
  }
  if (max_backtracks < 0) {
    return Error{"max local backtracks must be at least 0, got " + std::to_string(max_backtracks)};
  }
  return std::nullopt;
}

VertexBlockDescent::VertexBlockDescent(std::shared_ptr<const ClothModel> model,
                                       const VbdSettings& options)
    : model_owner_(std::move(model)),
      model_(*model_owner_),
      options_(options),
      potential_(model_),
      coloring_(color_cloth_particles(model_)),
      x_(3 * model_.particle_count()),
      gradient_(3 * model_.particle_count()),
      previous_(3 * model_.particle_count()),
      before_sweep_(3 * model_.particle_count()),
      chebyshev_step_(3 * model_.particle_count()) {
  const int n = model_.particle_count();
  sweep_offsets_.push_back(0);
  chunk_offsets_.push_back(0);
  for (int c = 0; c < coloring_.color_count(); ++c) {
    for (int i : coloring_.members(c)) {
      if (!model_.pinned[static_cast<std::size_t>(i)]) sweep_particles_.push_back(i);
    }
    sweep_offsets_.push_back(static_cast<int>(sweep_particles_.size()));
    const int size = sweep_offsets_.back() - sweep_offsets_[sweep_offsets_.size() - 2];
    chunk_offsets_.push_back(chunk_offsets_.back() + (size + kSweepChunk - 1) / kSweepChunk);
  }
  chunk_totals_.resize(static_cast<std::size_t>(chunk_offsets_.back()));
  // Incidence lists by counting sort. A bend's coupling-only springs (stiffness 0) carry no
  // force and no dashpot, so they are left out; the bends are visited on their own.
  spring_start_.assign(static_cast<std::size_t>(n) + 1, 0);
  bend_start_.assign(static_cast<std::size_t>(n) + 1, 0);
  for (int s = 0; s < model_.spring_count(); ++s) {
    if (model_.stiffness[static_cast<std::size_t>(s)] <= 0.0) continue;
    for (int end : model_.springs[static_cast<std::size_t>(s)])
      ++spring_start_[static_cast<std::size_t>(end) + 1];
  }
  for (const auto& bend : model_.bends) {
    for (int p : bend) {
      if (p >= 0) ++bend_start_[static_cast<std::size_t>(p) + 1];
    }
  }
  for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
    spring_start_[i + 1] += spring_start_[i];
    bend_start_[i + 1] += bend_start_[i];
  }
  incident_springs_.resize(static_cast<std::size_t>(spring_start_.back()));
  incident_bends_.resize(static_cast<std::size_t>(bend_start_.back()));
  incident_length_.resize(incident_springs_.size());
  incident_axial_.resize(incident_springs_.size());
  std::vector<int> fill(spring_start_.begin(), spring_start_.end() - 1);
  for (int s = 0; s < model_.spring_count(); ++s) {
    if (model_.stiffness[static_cast<std::size_t>(s)] <= 0.0) continue;
    const auto [a, b] = model_.springs[static_cast<std::size_t>(s)];
    incident_springs_[static_cast<std::size_t>(fill[static_cast<std::size_t>(a)]++)] = {s, b};
    incident_springs_[static_cast<std::size_t>(fill[static_cast<std::size_t>(b)]++)] = {s, a};
  }
  fill.assign(bend_start_.begin(), bend_start_.end() - 1);
  for (int k = 0; k < model_.bend_count(); ++k) {
    const auto& bend = model_.bends[static_cast<std::size_t>(k)];
    for (int slot = 0; slot < bend_size(bend); ++slot) {
      const int p = bend[static_cast<std::size_t>(slot)];
      incident_bends_[static_cast<std::size_t>(fill[static_cast<std::size_t>(p)]++)] = {k, slot};
    }
  }
}

// g_i(x_i + step) - g_i(x_i): the change of every term of g that involves x_i, in the
// cancellation-free forms of IncrementalPotential::difference, so it resolves decreases far
// below the rounding of g itself. Reuses the spring lengths and dashpot displacements that
// update_particle() left in incident_length_ and incident_axial_ for this x_i.
double VertexBlockDescent::local_difference(int i, const Vec3& step) const {
  const Vec3 xi = at(x_, i);
  const std::vector<Vec3>& axes = potential_.damping_axes();
  const double mass = model_.mass[static_cast<std::size_t>(i)];
  double inertia = mass * step.dot(2.0 * (xi - at(potential_.predicted(), i)) + step);
  double elastic = 0.0, damping = 0.0;
  for (int e = spring_start_[static_cast<std::size_t>(i)];
       e < spring_start_[static_cast<std::size_t>(i) + 1]; ++e) {
    const auto eu = static_cast<std::size_t>(e);
    const auto [s, j] = incident_springs_[eu];
    const auto su = static_cast<std::size_t>(s);
    const Vec3 d = xi - at(x_, j);
    const double sum = incident_length_[eu] + (d + step).norm();
    const double dl = sum > 0.0 ? step.dot(2.0 * d + step) / sum : 0.0;
    elastic += 0.5 * model_.stiffness[su] * dl * (sum - 2.0 * model_.rest_length[su]);
    const double dq = step.dot(axes[su]);
    damping += dq * (2.0 * incident_axial_[eu] + dq);
  }
  for (int e = bend_start_[static_cast<std::size_t>(i)];
       e < bend_start_[static_cast<std::size_t>(i) + 1]; ++e) {
    const auto [k, slot] = incident_bends_[static_cast<std::size_t>(e)];
    const auto ku = static_cast<std::size_t>(k);
    const Vec3 bend = bend_vector(x_, model_.bends[ku], model_.bend_weights[ku]);
    const Vec3 moved = model_.bend_weights[ku][static_cast<std::size_t>(slot)] * step;
    elastic +=
        0.5 * model_.bend_stiffness[static_cast<std::size_t>(k)] * moved.dot(2.0 * bend + moved);
  }
  return 0.5 * inv_h2_ * inertia + elastic + 0.5 * dashpot_ * damping;
}

void VertexBlockDescent::update_particle(int i, SweepTotals& totals) {
  const Vec3 xi = at(x_, i);
  const Eigen::VectorXd& start = potential_.start();
  const std::vector<Vec3>& axes = potential_.damping_axes();
  const double inertia = model_.mass[static_cast<std::size_t>(i)] * inv_h2_;
  // The local gradient and Hessian (VBD eq. 8-9): inertia, springs with their dashpots, bends
  // (constant c w_i^2 I). Each spring's gradient k (l - L) / l d and projected block
  // k [(1 - t) u u^T + t I], t = max(1 - L/l, 0), as in spring_energy.h, fused to one sqrt.
  Vec3 gradient = inertia * (xi - at(potential_.predicted(), i));
  Mat3 hessian = Mat3::Identity() * inertia;
  for (int e = spring_start_[static_cast<std::size_t>(i)];
       e < spring_start_[static_cast<std::size_t>(i) + 1]; ++e) {
    const auto eu = static_cast<std::size_t>(e);
    const auto [s, j] = incident_springs_[eu];
    const auto su = static_cast<std::size_t>(s);
    const Vec3 xj = at(x_, j);
    const double k = model_.stiffness[su], rest = model_.rest_length[su];
    const Vec3 d = xi - xj;
    const double length2 = d.squaredNorm();
    const double length = std::sqrt(length2);
    incident_length_[eu] = length;
    if (length2 > 0.0) {
      const double inverse = 1.0 / length;
      gradient += (k * (length - rest) * inverse) * d;
      const double transverse = std::max(1.0 - rest * inverse, 0.0);
      hessian.noalias() += (k * (1.0 - transverse) * inverse * inverse) * (d * d.transpose());
      hessian.diagonal().array() += k * transverse;
    } else {
      hessian.diagonal().array() += k;  // coincident: spring_hessian_block's k I stand-in
    }
    const Vec3& u = axes[su];
    const double q = (d - at(start, i) + at(start, j)).dot(u);
    incident_axial_[eu] = q;
    gradient += (dashpot_ * q) * u;
    hessian.noalias() += dashpot_ * (u * u.transpose());
  }
  double bend_diagonal = 0.0;
  for (int e = bend_start_[static_cast<std::size_t>(i)];
       e < bend_start_[static_cast<std::size_t>(i) + 1]; ++e) {
    const auto [k, slot] = incident_bends_[static_cast<std::size_t>(e)];
    const auto ku = static_cast<std::size_t>(k);
    const double c = model_.bend_stiffness[ku];
    const double w = model_.bend_weights[ku][static_cast<std::size_t>(slot)];
    gradient += (c * w) * bend_vector(x_, model_.bends[ku], model_.bend_weights[ku]);
    bend_diagonal += c * w * w;
  }
  hessian.diagonal().array() += bend_diagonal;

  // H_i >= m_i/h^2 I > 0, so the Cholesky factorization only fails on non-finite input; the
  // paper's guard against a near-singular H_i (skip the particle) covers that case.
  const Eigen::LLT<Mat3> llt(hessian);
  if (llt.info() != Eigen::Success) return;
  const Vec3 direction = llt.solve(-gradient);
  const double slope = gradient.dot(direction);
  if (!(slope < 0.0)) return;  // zero gradient, or rounding: nothing to gain here

  // Local backtracking (Armijo on g_i): what keeps the sweep's decrease of g non-positive.
  double alpha = 1.0;
  for (int t = 0; t <= options_.max_backtracks; ++t, alpha *= 0.5) {
    const Vec3 step = alpha * direction;
    const double decrease = local_difference(i, step);
    if (decrease <= options_.gamma * alpha * slope) {
      x_.segment<3>(3 * i) += step;
      totals.decrease += decrease;
      totals.slope += alpha * slope;
      totals.backtracks += t;
      ++totals.moved;
      return;
    }
  }
  totals.backtracks += options_.max_backtracks;  // no decrease found: the particle stays
}

void VertexBlockDescent::sweep(SweepTotals& totals) {
  // Colour by colour; within a colour the particles share no element, so their updates are
  // independent and split over threads in chunks of kSweepChunk. Each chunk sums its own
  // totals in particle order and the chunks are added in sweep order afterwards, so the
  // result is the same for any thread count.
  const auto run_chunk = [this](std::size_t c, int k) {
    const int begin = sweep_offsets_[c], end = sweep_offsets_[c + 1];
    SweepTotals chunk;
    const int stop = std::min(end, begin + (k + 1) * kSweepChunk);
    for (int e = begin + k * kSweepChunk; e < stop; ++e)
      update_particle(sweep_particles_[static_cast<std::size_t>(e)], chunk);
    chunk_totals_[static_cast<std::size_t>(chunk_offsets_[c] + k)] = chunk;
  };
  const int threads = parallel::threads_for(static_cast<int>(sweep_particles_.size()));
  if (threads == 1) {
    for (std::size_t c = 0; c + 1 < sweep_offsets_.size(); ++c) {
      for (int k = 0; k < chunk_offsets_[c + 1] - chunk_offsets_[c]; ++k) run_chunk(c, k);
    }
  } else {
    for (std::size_t c = 0; c + 1 < sweep_offsets_.size(); ++c) {
      const auto colour_chunk = [&](int k) { run_chunk(c, k); };
      parallel::run_tasks(chunk_offsets_[c + 1] - chunk_offsets_[c], threads, colour_chunk);
    }
  }
  for (const SweepTotals& chunk : chunk_totals_) {
    totals.decrease += chunk.decrease;
    totals.slope += chunk.slope;
    totals.backtracks += chunk.backtracks;
    totals.moved += chunk.moved;
  }
}

// Chebyshev semi-iterative acceleration (Wang 2015, eq. 11-12; VBD section 3.8):
//   x_{k+1} = omega_{k+1} (xhat_{k+1} - x_{k-1}) + x_{k-1},
//   omega_1 = 1, omega_2 = 2 / (2 - rho^2), omega_{k+1} = 4 / (4 - rho^2 omega_k),
// with xhat_{k+1} the sweep's result. The accelerated point is kept only if g does not increase
// from xhat (checked with the cancellation-free difference); otherwise the schedule restarts.
// `iteration` counts sweeps since the last restart; returns whether the extrapolation was kept.
bool VertexBlockDescent::chebyshev(int iteration, double& omega, IterationRecord& record,
                                   StepReport& report) {
  const double rho2 = options_.chebyshev_rho * options_.chebyshev_rho;
  omega = iteration == 0 ? 1.0 : iteration == 1 ? 2.0 / (2.0 - rho2) : 4.0 / (4.0 - rho2 * omega);
  if (iteration == 0) return true;
  const auto t = StageClock::now();
  chebyshev_step_ = (omega - 1.0) * (x_ - previous_);
  const double decrease = potential_.difference(x_, chebyshev_step_);
  report.ms_line_search += ms_since(t);
  if (!(decrease <= 0.0)) return false;
  x_ += chebyshev_step_;
  record.decrease += decrease;
  return true;
}

void VertexBlockDescent::step(ClothState& state, double h, StepReport& report,
                              const Eigen::VectorXd* external_forces) {
  const auto substep_start = StageClock::now();
  auto t = substep_start;
  potential_.prepare(state, h, external_forces);
  inv_h2_ = 1.0 / (h * h);
  dashpot_ = model_.damping / h;
  // Start from y, as Newton does: the stopping test is relative to |grad g(y)| whatever the
  // start, and every solver then begins from the same point.
  x_ = potential_.predicted();
  potential_.gradient(x_, gradient_);
  double gradient_norm = gradient_.norm();
  report.ms_gradient += ms_since(t);

  const GradientStop test =
      begin_implicit_substep(potential_, gradient_norm, options_.tolerance, report);
  bool converged = test.reached(gradient_norm);
  const bool accelerate = options_.chebyshev_rho > 0.0;
  int chebyshev_iteration = 0;
  double omega = 1.0;
  bool checked = true;  // gradient_norm belongs to the current x
  for (int k = 0; !converged && std::isfinite(gradient_norm) && k < options_.max_iterations; ++k) {
    IterationRecord record;
    if (options_.record_iterations) record.objective = potential_.value(x_);
    if (accelerate) before_sweep_ = x_;

    t = StageClock::now();
    SweepTotals totals;
    sweep(totals);
    report.ms_linear_solve += ms_since(t);
    report.line_search_steps += totals.backtracks;
    if (totals.moved == 0) break;  // no particle can decrease g: stalled at rounding
    ++report.newton_iterations;
    checked = false;
    record.decrease = totals.decrease;
    record.slope = totals.slope;
    record.line_search_steps = totals.backtracks;
    record.alpha = 1.0;

    if (accelerate) {
      const bool kept = chebyshev(chebyshev_iteration, omega, record, report);
      record.alpha = kept ? omega : 1.0;
      chebyshev_iteration = kept ? chebyshev_iteration + 1 : 0;
      previous_ = before_sweep_;
    }

    const bool check = options_.record_iterations || (k + 1) % options_.check_interval == 0 ||
                       k + 1 == options_.max_iterations;
    if (check) {
      t = StageClock::now();
      potential_.gradient(x_, gradient_);
      gradient_norm = gradient_.norm();
      report.ms_gradient += ms_since(t);
      converged = test.reached(gradient_norm);
      checked = true;
    }
    if (options_.record_iterations) {
      record.gradient_norm = gradient_norm;
      record.ms = ms_since(substep_start);
      record.objective_after = potential_.value(x_);
      report.iterations.push_back(record);
    }
  }
  if (!checked) {
    // A stall between checks left gradient_norm stale: test the final point.
    t = StageClock::now();
    potential_.gradient(x_, gradient_);
    gradient_norm = gradient_.norm();
    report.ms_gradient += ms_since(t);
    converged = test.reached(gradient_norm);
  }
  report.gradient_norm_end = gradient_norm;
  report.converged = report.converged && converged;

  finish_implicit_substep(model_, x_, h, state);
}

}  // namespace animkit
