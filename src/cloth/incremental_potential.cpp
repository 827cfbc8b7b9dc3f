#include "animkit/cloth/incremental_potential.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "../core/parallel.h"
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
      damping_axis_(model.springs.size(), Vec3::Zero()),
      incidence_(model),
      bend_coupling_(model.springs.size(), 0.0),
      spring_term_(model.springs.size()),
      bend_term_(model.bends.size()),
      partials_(static_cast<std::size_t>(parallel::chunk_count(
          std::max({model.particle_count(), model.spring_count(), model.bend_count()})))) {
  for (int k = 0; k < model.spring_count(); ++k) {
    spring_force_scale_ += std::pow(model.stiffness[k] * model.rest_length[k], 2);
  }
  spring_force_scale_ = std::sqrt(spring_force_scale_);
  // Bends: constant blocks on their three springs (see bend_energy.h).
  for (int k = 0; k < model.bend_count(); ++k) {
    for (int j = 0; j < 3; ++j)
      bend_coupling_[model.bend_springs[k][j]] += kBendCouplings[j] * model.bend_stiffness[k];
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
    const auto [a, b, c] = model_.bends[k];
    acc[0] += bend_energy(at(x, a), at(x, b), at(x, c), model_.bend_stiffness[k]);
  })[0];
  return inertia / (2.0 * h_ * h_) + (springs[0] + bends) +
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
    const auto [a, b, c] = model_.bends[k];
    const Vec3 e = bend_vector(at(x, a), at(x, b), at(x, c));
    const Vec3 de = bend_vector(at(step, a), at(step, b), at(step, c));
    acc[0] += 0.5 * model_.bend_stiffness[k] * de.dot(2.0 * e + de);
  })[0];
  return inertia / (2.0 * h_ * h_) + (springs[0] + bends) +
         model_.damping / (2.0 * h_) * springs[1];
}

void IncrementalPotential::gradient(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) const {
  // Per spring, its force on a (minus that on b) with its dashpot; per bend, c e.
  const double c = model_.damping / h_;
  parallel::for_each(model_.spring_count(), [&](int s) {
    const auto [a, b] = model_.springs[s];
    const Vec3& u = damping_axis_[s];
    const double axial = (at(x, a) - at(x_start_, a) - at(x, b) + at(x_start_, b)).dot(u);
    spring_term_[s] =
        spring_gradient(at(x, a), at(x, b), model_.stiffness[s], model_.rest_length[s]) +
        (c * axial) * u;
  });
  parallel::for_each(model_.bend_count(), [&](int k) {
    const auto& p = model_.bends[k];
    bend_term_[k] = model_.bend_stiffness[k] * bend_vector(at(x, p[0]), at(x, p[1]), at(x, p[2]));
  });
  // Per particle: inertia, then its springs and bends in element order.
  const double inv_h2 = 1.0 / (h_ * h_);
  const ParticleIncidence& in = incidence_;
  parallel::for_each(model_.particle_count(), [&](int i) {
    if (model_.pinned[i]) {
      gradient.segment<3>(3 * i).setZero();
      return;
    }
    Vec3 g = (model_.mass[i] * inv_h2) * (at(x, i) - at(y_, i));
    for (int e = in.spring_start[i]; e < in.spring_start[i + 1]; ++e) {
      const int entry = in.spring_entry[e];
      if (entry & 1) {
        g -= spring_term_[entry >> 1];
      } else {
        g += spring_term_[entry >> 1];
      }
    }
    for (int e = in.bend_start[i]; e < in.bend_start[i + 1]; ++e) {
      const int entry = in.bend_entry[e];
      g += kBendWeights[entry % 3] * bend_term_[entry / 3];
    }
    gradient.segment<3>(3 * i) = g;
  });
}

void IncrementalPotential::hessian(const Eigen::VectorXd& x, BlockHessian& blocks,
                                   bool projected) const {
  // Per spring its block K (a pinned end: the products act on the free end only), then per
  // particle its diagonal block M / h^2 + the sum of its springs' K in spring order.
  const double c = model_.damping / h_;
  parallel::for_each(model_.spring_count(), [&](int s) {
    const auto [a, b] = model_.springs[s];
    const Vec3& u = damping_axis_[s];
    Mat3 k = spring_hessian_block(at(x, a), at(x, b), model_.stiffness[s], model_.rest_length[s],
                                  projected) +
             c * (u * u.transpose());
    k.diagonal().array() += bend_coupling_[s];
    blocks.coupling[s] = k;
  });
  const double inv_h2 = 1.0 / (h_ * h_);
  const ParticleIncidence& in = incidence_;
  parallel::for_each(model_.particle_count(), [&](int i) {
    if (model_.pinned[i]) {
      blocks.inertia[i] = 1.0;
      blocks.diagonal[i] = Mat3::Identity();
      return;
    }
    blocks.inertia[i] = model_.mass[i] * inv_h2;
    Mat3 d = Mat3::Identity() * blocks.inertia[i];
    for (int e = in.spring_start[i]; e < in.spring_start[i + 1]; ++e)
      d += blocks.coupling[in.spring_entry[e] >> 1];
    blocks.diagonal[i] = d;
  });
}

}  // namespace animkit
