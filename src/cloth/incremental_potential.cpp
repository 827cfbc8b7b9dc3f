#include "animkit/cloth/incremental_potential.h"

#include <cassert>
#include <cmath>
#include <limits>

#include "animkit/cloth/bend_energy.h"
#include "animkit/cloth/spring_energy.h"

namespace animkit {

namespace {
Vec3 at(const Eigen::VectorXd& v, int i) {
  return v.segment<3>(3 * i);
}
}  // namespace

IncrementalPotential::IncrementalPotential(const ClothModel& model)
    : model_(model),
      y_(3 * model.particle_count()),
      x_start_(3 * model.particle_count()),
      damping_axis_(model.springs.size(), Vec3::Zero()) {
  for (int k = 0; k < model.spring_count(); ++k) {
    spring_force_scale_ += std::pow(model.stiffness[k] * model.rest_length[k], 2);
  }
  spring_force_scale_ = std::sqrt(spring_force_scale_);
}

void IncrementalPotential::prepare(const ClothState& state, double h,
                                   const Eigen::VectorXd* external_forces) {
  assert(h > 0.0);
  h_ = h;
  x_start_ = state.positions;
  for (int i = 0; i < model_.particle_count(); ++i) {
    if (model_.pinned[i]) {
      y_.segment<3>(3 * i) = at(state.positions, i);
    } else {
      y_.segment<3>(3 * i) = at(state.positions, i) + h * at(state.velocities, i) +
                             Vec3(0.0, -h * h * model_.gravity, 0.0);
      if (external_forces) {
        y_.segment<3>(3 * i) += (h * h / model_.mass[i]) * at(*external_forces, i);
      }
    }
  }
  double inertia_scale = 0.0;  // |M y|^2
  for (int i = 0; i < model_.particle_count(); ++i) {
    inertia_scale += model_.mass[i] * model_.mass[i] * y_.segment<3>(3 * i).squaredNorm();
  }
  constexpr double kRounding = 16.0 * std::numeric_limits<double>::epsilon();
  gradient_floor_ = kRounding * (std::sqrt(inertia_scale) / (h * h) + spring_force_scale_);
  for (int s = 0; s < model_.spring_count(); ++s) {
    const auto [a, b] = model_.springs[s];
    const Vec3 d = at(x_start_, a) - at(x_start_, b);
    const double length = d.norm();
    // No dashpot on a degenerate spring, nor on a bend's coupling-only spring (stiffness 0).
    damping_axis_[s] = length > 0.0 && model_.stiffness[s] > 0.0 ? Vec3(d / length) : Vec3::Zero();
  }
  for (const auto& term : terms_) term->prepare(state, h);
}

double IncrementalPotential::value(const Eigen::VectorXd& x) const {
  double inertia = 0.0;
  for (int i = 0; i < model_.particle_count(); ++i) {
    inertia += model_.mass[i] * (at(x, i) - at(y_, i)).squaredNorm();
  }
  double elastic = 0.0, damping = 0.0;
  for (int s = 0; s < model_.spring_count(); ++s) {
    const auto [a, b] = model_.springs[s];
    elastic += spring_energy(at(x, a), at(x, b), model_.stiffness[s], model_.rest_length[s]);
    const double axial =
        (at(x, a) - at(x_start_, a) - at(x, b) + at(x_start_, b)).dot(damping_axis_[s]);
    damping += axial * axial;
  }
  for (int k = 0; k < model_.bend_count(); ++k) {
    const auto [a, b, c] = model_.bends[k];
    elastic += bend_energy(at(x, a), at(x, b), at(x, c), model_.bend_stiffness[k]);
  }
  for (const auto& term : terms_) elastic += term->value(x);
  return inertia / (2.0 * h_ * h_) + elastic + model_.damping / (2.0 * h_) * damping;
}

double IncrementalPotential::difference(const Eigen::VectorXd& x,
                                        const Eigen::VectorXd& step) const {
  double inertia = 0.0;
  for (int i = 0; i < model_.particle_count(); ++i) {
    const Vec3 s = at(step, i);
    inertia += model_.mass[i] * s.dot(2.0 * (at(x, i) - at(y_, i)) + s);
  }
  double elastic = 0.0, damping = 0.0;
  for (int k = 0; k < model_.spring_count(); ++k) {
    const auto [a, b] = model_.springs[k];
    const Vec3 d = at(x, a) - at(x, b);
    const Vec3 ds = at(step, a) - at(step, b);
    const double l = d.norm(), l_new = (d + ds).norm();
    // l' - l = (|d + ds|^2 - |d|^2) / (l' + l) = ds.(2d + ds) / (l' + l);
    // E' - E = 1/2 k (l' - l)(l' + l - 2L).
    const double sum = l + l_new;
    const double dl = sum > 0.0 ? ds.dot(2.0 * d + ds) / sum : 0.0;
    elastic += 0.5 * model_.stiffness[k] * dl * (sum - 2.0 * model_.rest_length[k]);
    // ((q + dq)^2 - q^2) = dq (2q + dq), q the axial displacement since x_n.
    const Vec3& u = damping_axis_[k];
    const double q = (d - (at(x_start_, a) - at(x_start_, b))).dot(u);
    const double dq = ds.dot(u);
    damping += dq * (2.0 * q + dq);
  }
  for (int k = 0; k < model_.bend_count(); ++k) {
    // |e + de|^2 - |e|^2 = de.(2e + de).
    const auto [a, b, c] = model_.bends[k];
    const Vec3 e = bend_vector(at(x, a), at(x, b), at(x, c));
    const Vec3 de = bend_vector(at(step, a), at(step, b), at(step, c));
    elastic += 0.5 * model_.bend_stiffness[k] * de.dot(2.0 * e + de);
  }
  for (const auto& term : terms_) elastic += term->difference(x, step);
  return inertia / (2.0 * h_ * h_) + elastic + model_.damping / (2.0 * h_) * damping;
}

void IncrementalPotential::gradient(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) const {
  const double inv_h2 = 1.0 / (h_ * h_);
  for (int i = 0; i < model_.particle_count(); ++i) {
    gradient.segment<3>(3 * i) = (model_.mass[i] * inv_h2) * (at(x, i) - at(y_, i));
  }
  const double c = model_.damping / h_;
  for (int s = 0; s < model_.spring_count(); ++s) {
    const auto [a, b] = model_.springs[s];
    const Vec3& u = damping_axis_[s];
    const double axial = (at(x, a) - at(x_start_, a) - at(x, b) + at(x_start_, b)).dot(u);
    const Vec3 g = spring_gradient(at(x, a), at(x, b), model_.stiffness[s], model_.rest_length[s]) +
                   (c * axial) * u;
    gradient.segment<3>(3 * a) += g;
    gradient.segment<3>(3 * b) -= g;
  }
  for (int k = 0; k < model_.bend_count(); ++k) {
    const auto& particles = model_.bends[k];
    const Vec3 e = model_.bend_stiffness[k] *
                   bend_vector(at(x, particles[0]), at(x, particles[1]), at(x, particles[2]));
    for (int j = 0; j < 3; ++j) gradient.segment<3>(3 * particles[j]) += kBendWeights[j] * e;
  }
  for (const auto& term : terms_) term->add_gradient(x, gradient);
  for (int i = 0; i < model_.particle_count(); ++i) {
    if (model_.pinned[i]) gradient.segment<3>(3 * i).setZero();
  }
}

void IncrementalPotential::hessian(const Eigen::VectorXd& x, BlockHessian& blocks,
                                   bool projected) const {
  const double inv_h2 = 1.0 / (h_ * h_);
  for (int i = 0; i < model_.particle_count(); ++i) {
    blocks.inertia[i] = model_.pinned[i] ? 1.0 : model_.mass[i] * inv_h2;
    blocks.diagonal[i] = Mat3::Identity() * blocks.inertia[i];
  }
  const double c = model_.damping / h_;
  for (int s = 0; s < model_.spring_count(); ++s) {
    const auto [a, b] = model_.springs[s];
    const Vec3& u = damping_axis_[s];
    const Mat3 k = spring_hessian_block(at(x, a), at(x, b), model_.stiffness[s],
                                        model_.rest_length[s], projected) +
                   c * (u * u.transpose());
    const bool free_a = !model_.pinned[a], free_b = !model_.pinned[b];
    if (free_a) blocks.diagonal[a] += k;
    if (free_b) blocks.diagonal[b] += k;
    blocks.coupling[s] = k;  // a pinned end: the products act on the free end only
  }
  // Bends: constant blocks on their three springs (see bend_energy.h).
  for (int k = 0; k < model_.bend_count(); ++k) {
    for (int j = 0; j < 3; ++j) {
      const int s = model_.bend_springs[k][j];
      const double coupling = kBendCouplings[j] * model_.bend_stiffness[k];
      const auto [a, b] = model_.springs[s];
      if (!model_.pinned[a]) blocks.diagonal[a].diagonal().array() += coupling;
      if (!model_.pinned[b]) blocks.diagonal[b].diagonal().array() += coupling;
      blocks.coupling[s].diagonal().array() += coupling;
    }
  }
  add_term_hessians(x, blocks, projected);
}

void IncrementalPotential::add_term_hessians(const Eigen::VectorXd& x, BlockHessian& blocks,
                                             bool projected) const {
  blocks.extra.clear();
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
