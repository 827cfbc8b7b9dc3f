#include "animkit/cloth/explicit_euler.h"

#include "animkit/cloth/bend_energy.h"

namespace animkit {

void cloth_forces(const ClothModel& model, const Eigen::VectorXd& positions,
                  const Eigen::VectorXd& velocities, Eigen::VectorXd& forces) {
  for (int i = 0; i < model.particle_count(); ++i) {
    forces.segment<3>(3 * i) = Vec3(0.0, -model.mass[i] * model.gravity, 0.0);
  }
  for (int s = 0; s < model.spring_count(); ++s) {
    const auto [a, b] = model.springs[s];
    const Vec3 d = positions.segment<3>(3 * b) - positions.segment<3>(3 * a);
    const double length = d.norm();
    // No direction: the spring cannot push either way. Stiffness 0: a bend's coupling spring.
    if (length == 0.0 || model.stiffness[s] == 0.0) continue;
    const Vec3 u = d / length;
    const double relative_speed =
        (velocities.segment<3>(3 * b) - velocities.segment<3>(3 * a)).dot(u);
    // The lab's spring force on a: (k (l - L) + c (v_b - v_a).u) u; b gets the opposite.
    const Vec3 f =
        (model.stiffness[s] * (length - model.rest_length[s]) + model.damping * relative_speed) * u;
    forces.segment<3>(3 * a) += f;
    forces.segment<3>(3 * b) -= f;
  }
  for (int k = 0; k < model.bend_count(); ++k) {
    const auto& p = model.bends[k];
    const auto& w = model.bend_weights[k];
    const Vec3 e = model.bend_stiffness[k] * bend_vector(positions, p, w);
    for (int j = 0; j < bend_size(p); ++j) forces.segment<3>(3 * p[j]) -= w[j] * e;
  }
}

ExplicitEuler::ExplicitEuler(std::shared_ptr<const ClothModel> model)
    : model_owner_(std::move(model)), model_(*model_owner_), forces_(3 * model_.particle_count()) {}

void ExplicitEuler::step(ClothState& state, double h, StepReport& report,
                         const Eigen::VectorXd* external_forces) {
  cloth_forces(model_, state.positions, state.velocities, forces_);
  if (external_forces) forces_ += *external_forces;
  for (int i = 0; i < model_.particle_count(); ++i) {
    if (model_.pinned[i]) continue;
    state.velocities.segment<3>(3 * i) += (h / model_.mass[i]) * forces_.segment<3>(3 * i);
    state.positions.segment<3>(3 * i) += h * state.velocities.segment<3>(3 * i);
  }
  ++report.substeps_done;
}

}  // namespace animkit
