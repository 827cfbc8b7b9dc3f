#include "animkit/cloth/incremental_potential.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "../core/parallel.h"
#include "animkit/cloth/bend_energy.h"
#include "animkit/cloth/spring_energy.h"
#include "stacked_vectors.h"

namespace animkit {

IncrementalPotential::IncrementalPotential(const ClothModel& model)
    : model_(model),
      y_(3 * model.particle_count()),
      x_start_(3 * model.particle_count()),
      damping_axis_(model.springs.size(), Vec3::Zero()),
      spring_schedule_(model.springs, model.particle_count()),
      bend_schedule_(model.bends, model.particle_count()),
      bend_coupling_(model.springs.size(), 0.0),
      partials_(static_cast<std::size_t>(parallel::chunk_count(
          std::max({model.particle_count(), model.spring_count(), model.bend_count()})))) {
  for (int k = 0; k < model.spring_count(); ++k) {
    spring_force_scale_ += std::pow(model.stiffness[k] * model.rest_length[k], 2);
  }
  spring_force_scale_ = std::sqrt(spring_force_scale_);
  // Bends: constant blocks on the springs of their particle pairs (see bend_energy.h).
  for (int k = 0; k < model.bend_count(); ++k) {
    for (std::size_t q = 0; q < kBendPairs.size(); ++q) {
      const int s = model.bend_springs[k][q];
      if (s < 0) continue;
      bend_coupling_[s] += bend_coupling(model.bend_weights[k], kBendPairs[q][0], kBendPairs[q][1],
                                         model.bend_stiffness[k]);
    }
  }
}

void IncrementalPotential::prepare(const ClothState& state, double h,
                                   const Eigen::VectorXd* external_forces) {
  assert(h > 0.0);
  h_ = h;
  x_start_ = state.positions;
  parallel::for_each(model_.particle_count(), [&](int i) {
    if (model_.pinned[i]) {
      y_.segment<3>(3 * i) = at(state.positions, i);
    } else {
      y_.segment<3>(3 * i) = at(state.positions, i) + h * at(state.velocities, i) +
                             Vec3(0.0, -h * h * model_.gravity, 0.0);
      if (external_forces) {
        y_.segment<3>(3 * i) += (h * h / model_.mass[i]) * at(*external_forces, i);
      }
    }
  });
  const double inertia_scale =  // |M y|^2
      parallel::sum<2>(model_.particle_count(), partials_, [&](int i, std::array<double, 2>& acc) {
        acc[0] += model_.mass[i] * model_.mass[i] * y_.segment<3>(3 * i).squaredNorm();
      })[0];
  constexpr double kRounding = 16.0 * std::numeric_limits<double>::epsilon();
  gradient_floor_ = kRounding * (std::sqrt(inertia_scale) / (h * h) + spring_force_scale_);
  parallel::for_each(model_.spring_count(), [&](int s) {
    const auto [a, b] = model_.springs[s];
    const Vec3 d = at(x_start_, a) - at(x_start_, b);
    const double length = d.norm();
    // No dashpot on a degenerate spring, nor on a bend's coupling-only spring (stiffness 0).
    damping_axis_[s] = length > 0.0 && model_.stiffness[s] > 0.0 ? Vec3(d / length) : Vec3::Zero();
  });
  for (const auto& term : terms_) term->prepare(state, h);
}

void IncrementalPotential::advance_terms(Eigen::VectorXd& x) {
  for (const auto& term : terms_) term->advance(x);
}

void IncrementalPotential::update_terms(const Eigen::VectorXd& x) {
  for (const auto& term : terms_) term->update(x);
}

bool IncrementalPotential::relag_terms(const Eigen::VectorXd& x) {
  bool changed = false;
  for (const auto& term : terms_) changed = term->relag(x) || changed;  // every term, always
  return changed;
}

bool IncrementalPotential::terms_settled() const {
  return std::all_of(terms_.begin(), terms_.end(),
                     [](const auto& term) { return term->settled(); });
}

bool IncrementalPotential::terms_gaps_settled(const Eigen::VectorXd& x,
                                              const Eigen::VectorXd& dx) const {
  return std::all_of(terms_.begin(), terms_.end(),
                     [&](const auto& term) { return term->gaps_settled(x, dx); });
}

double IncrementalPotential::max_step(const Eigen::VectorXd& x, const Eigen::VectorXd& step) {
  double bound = 1.0;
  for (const auto& term : terms_) bound = std::min(bound, term->max_step(x, step));
  return bound;
}

double IncrementalPotential::value(const Eigen::VectorXd& x) const {
  using Acc = std::array<double, 2>;
  const double inertia = parallel::sum<2>(model_.particle_count(), partials_, [&](int i, Acc& acc) {
    acc[0] += model_.mass[i] * (at(x, i) - at(y_, i)).squaredNorm();
  })[0];
  // [0]: elastic, [1]: the dashpots' sum of squared axial displacements.
  const Acc springs = parallel::sum<2>(model_.spring_count(), partials_, [&](int s, Acc& acc) {
    const auto [a, b] = model_.springs[s];
    acc[0] += spring_energy(at(x, a), at(x, b), model_.stiffness[s], model_.rest_length[s]);
    const double axial =
        (at(x, a) - at(x_start_, a) - at(x, b) + at(x_start_, b)).dot(damping_axis_[s]);
    acc[1] += axial * axial;
  });
  const double bends = parallel::sum<2>(model_.bend_count(), partials_, [&](int k, Acc& acc) {
    acc[0] += bend_energy(x, model_.bends[k], model_.bend_weights[k], model_.bend_stiffness[k]);
  })[0];
  double terms = 0.0;
  for (const auto& term : terms_) terms += term->value(x);
  return inertia / (2.0 * h_ * h_) + (springs[0] + bends + terms) +
         model_.damping / (2.0 * h_) * springs[1];
}

double IncrementalPotential::difference(const Eigen::VectorXd& x,
                                        const Eigen::VectorXd& step) const {
  using Acc = std::array<double, 2>;
  const double inertia = parallel::sum<2>(model_.particle_count(), partials_, [&](int i, Acc& acc) {
    const Vec3 s = at(step, i);
    acc[0] += model_.mass[i] * s.dot(2.0 * (at(x, i) - at(y_, i)) + s);
  })[0];
  // [0]: elastic change, [1]: change of the dashpots' sum of squares.
  const Acc springs = parallel::sum<2>(model_.spring_count(), partials_, [&](int k, Acc& acc) {
    const auto [a, b] = model_.springs[k];
    const Vec3 d = at(x, a) - at(x, b);
    const Vec3 ds = at(step, a) - at(step, b);
    const double l = d.norm(), l_new = (d + ds).norm();
    // l' - l = (|d + ds|^2 - |d|^2) / (l' + l) = ds.(2d + ds) / (l' + l);
    // E' - E = 1/2 k (l' - l)(l' + l - 2L).
    const double sum = l + l_new;
    const double dl = sum > 0.0 ? ds.dot(2.0 * d + ds) / sum : 0.0;
    acc[0] += 0.5 * model_.stiffness[k] * dl * (sum - 2.0 * model_.rest_length[k]);
    // ((q + dq)^2 - q^2) = dq (2q + dq), q the axial displacement since x_n.
    const Vec3& u = damping_axis_[k];
    const double q = (d - (at(x_start_, a) - at(x_start_, b))).dot(u);
    const double dq = ds.dot(u);
    acc[1] += dq * (2.0 * q + dq);
  });
  const double bends = parallel::sum<2>(model_.bend_count(), partials_, [&](int k, Acc& acc) {
    // |e + de|^2 - |e|^2 = de.(2e + de).
    const Vec3 e = bend_vector(x, model_.bends[k], model_.bend_weights[k]);
    const Vec3 de = bend_vector(step, model_.bends[k], model_.bend_weights[k]);
    acc[0] += 0.5 * model_.bend_stiffness[k] * de.dot(2.0 * e + de);
  })[0];
  double terms = 0.0;
  for (const auto& term : terms_) terms += term->difference(x, step);
  return inertia / (2.0 * h_ * h_) + (springs[0] + bends + terms) +
         model_.damping / (2.0 * h_) * springs[1];
}

void IncrementalPotential::gradient(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) const {
  const double inv_h2 = 1.0 / (h_ * h_);
  parallel::for_each(model_.particle_count(), [&](int i) {
    gradient.segment<3>(3 * i) = (model_.mass[i] * inv_h2) * (at(x, i) - at(y_, i));
  });
  const double c = model_.damping / h_;
  parallel::scatter(spring_schedule_, [&](int s) {
    const auto [a, b] = model_.springs[s];
    const Vec3& u = damping_axis_[s];
    const double axial = (at(x, a) - at(x_start_, a) - at(x, b) + at(x_start_, b)).dot(u);
    const Vec3 g = spring_gradient(at(x, a), at(x, b), model_.stiffness[s], model_.rest_length[s]) +
                   (c * axial) * u;
    gradient.segment<3>(3 * a) += g;
    gradient.segment<3>(3 * b) -= g;
  });
  parallel::scatter(bend_schedule_, [&](int k) {
    const auto& particles = model_.bends[k];
    const auto& weights = model_.bend_weights[k];
    const Vec3 e = model_.bend_stiffness[k] * bend_vector(x, particles, weights);
    for (int j = 0; j < bend_size(particles); ++j)
      gradient.segment<3>(3 * particles[j]) += weights[j] * e;
  });
  for (const auto& term : terms_) term->add_gradient(x, gradient);
  parallel::for_each(model_.particle_count(), [&](int i) {
    if (model_.pinned[i]) gradient.segment<3>(3 * i).setZero();
  });
}

void IncrementalPotential::hessian(const Eigen::VectorXd& x, BlockHessian& blocks,
                                   bool projected) const {
  spring_hessian(x, blocks, projected);
  add_term_hessians(x, blocks, projected);
}

// During drape-sphere's impact the exact Hessian is indefinite in two Newton iterations of
// three; keeping the contact pairs' blocks for the retry takes a fifth off the Hessian's time
// (41 x 41, first 15 frames: 1.92 s against 2.41 s).
void IncrementalPotential::project_hessian(const Eigen::VectorXd& x, BlockHessian& blocks) const {
  const bool terms_ignore_projection = std::ranges::all_of(
      terms_, [](const auto& term) { return term->hessian_ignores_projection(); });
  if (!terms_ignore_projection) {
    hessian(x, blocks, true);
    return;
  }
  spring_hessian(x, blocks, true);
  // The terms' diagonal blocks again, in add_term_hessians' order: the same sums.
  for (const HessianBlock& block : blocks.extra)
    if (block.row == block.col) blocks.diagonal[block.row] += block.value;
}

// Inertia and springs: `diagonal` and `coupling` set, `extra` left as it is.
void IncrementalPotential::spring_hessian(const Eigen::VectorXd& x, BlockHessian& blocks,
                                          bool projected) const {
  const double inv_h2 = 1.0 / (h_ * h_);
  parallel::for_each(model_.particle_count(), [&](int i) {
    blocks.inertia[i] = model_.pinned[i] ? 1.0 : model_.mass[i] * inv_h2;
    blocks.diagonal[i] = Mat3::Identity() * blocks.inertia[i];
  });
  // Per spring its block K with its dashpot and its bends' constant part (bend_energy.h), added
  // to its free ends' diagonal blocks (a pinned end: the products act on the free end only).
  const double c = model_.damping / h_;
  parallel::scatter(spring_schedule_, [&](int s) {
    const auto [a, b] = model_.springs[s];
    const Vec3& u = damping_axis_[s];
    Mat3 k = spring_hessian_block(at(x, a), at(x, b), model_.stiffness[s], model_.rest_length[s],
                                  projected) +
             c * (u * u.transpose());
    k.diagonal().array() += bend_coupling_[s];
    if (!model_.pinned[a]) blocks.diagonal[a] += k;
    if (!model_.pinned[b]) blocks.diagonal[b] += k;
    blocks.coupling[s] = k;
  });
}

void IncrementalPotential::add_term_hessians(const Eigen::VectorXd& x, BlockHessian& blocks,
                                             bool projected) const {
  blocks.extra.clear();
  blocks.renew_terms_revision();
  for (const auto& term : terms_) {
    term_blocks_.clear();
    term->add_hessian(x, projected, term_blocks_);
    for (const HessianBlock& block : term_blocks_) {
      // A pinned particle is not an unknown: its row stays the identity's, and a block that
      // couples it to a free one would act on its (zero) entries only.
      if (model_.pinned[block.row] || model_.pinned[block.col]) continue;
      // `diagonal` is what preconditioners see; the products use `extra`.
      if (block.row == block.col) blocks.diagonal[block.row] += block.value;
      blocks.extra.push_back(block);
    }
  }
}

}  // namespace animkit
