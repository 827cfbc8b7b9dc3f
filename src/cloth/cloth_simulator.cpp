#include "animkit/cloth/cloth_simulator.h"

#include <array>
#include <chrono>
#include <cmath>
#include <string>

#include "animkit/cloth/integrator.h"
#include "animkit/cloth/integrator_registry.h"
#include "animkit/cloth/parameter_ranges.h"
#include "animkit/core/validation.h"

namespace animkit {

std::optional<Error> SimulationOptions::validate() const {
  if (substeps < 0 || substeps > kMaxSubsteps) {
    return Error{"substeps must be between 1 and " + std::to_string(kMaxSubsteps) +
                 " (or 0 for the default), got " + std::to_string(substeps)};
  }
  return animkit::validate(integrator);
}

int SimulationOptions::effective_substeps() const {
  return substeps > 0 ? substeps : integrator_entry(integrator).default_substeps;
}

struct ClothSimulator::Impl {
  std::shared_ptr<const ClothModel> model;  // shared with the integrator, never changed
  ClothState state;
  ClothState backup;  // the state before the current step, to undo a diverged one
  SimulationOptions options;
  std::unique_ptr<ClothIntegrator> integrator;
  std::optional<Eigen::VectorXd> external_forces;
  std::vector<std::shared_ptr<EnergyTerm>> terms;  // also the integrator's, for their reports
  int steps = 0;
};

ClothSimulator::ClothSimulator(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
ClothSimulator::ClothSimulator(ClothSimulator&&) noexcept = default;
ClothSimulator& ClothSimulator::operator=(ClothSimulator&&) noexcept = default;
ClothSimulator::~ClothSimulator() = default;

const ClothModel& ClothSimulator::model() const {
  return *impl_->model;
}
const ClothState& ClothSimulator::state() const {
  return impl_->state;
}
const SimulationOptions& ClothSimulator::options() const {
  return impl_->options;
}
int ClothSimulator::steps_taken() const {
  return impl_->steps;
}

Result<ClothSimulator> ClothSimulator::create(const ClothDesc& desc,
                                              const SimulationOptions& options) {
  if (auto error = options.validate()) return fail(error->message);
  auto built = build_cloth(desc);
  if (!built) return fail(built.error().message);
  auto impl = std::make_unique<Impl>();
  impl->model = std::make_shared<const ClothModel>(std::move(built->model));
  impl->state = std::move(built->state);
  impl->backup = impl->state;
  impl->options = options;
  impl->integrator = make_integrator(impl->model, options.integrator);
  return ClothSimulator(std::move(impl));
}

namespace {

// The first particle whose position or velocity is non-finite or beyond kExplodedMagnitude.
std::optional<std::string> divergence(const ClothState& state) {
  const auto bad = [](const Vec3& v) {
    return !is_finite(v) || v.cwiseAbs().maxCoeff() > kExplodedMagnitude;
  };
  for (Eigen::Index i = 0; i < state.positions.size() / 3; ++i) {
    const int p = static_cast<int>(i);
    if (bad(state.position(p))) {
      return "particle " + std::to_string(p) + " position is " +
             (is_finite(state.position(p)) ? "beyond 1e8" : "not finite");
    }
    if (bad(state.velocity(p))) {
      return "particle " + std::to_string(p) + " velocity is " +
             (is_finite(state.velocity(p)) ? "beyond 1e8" : "not finite");
    }
  }
  return std::nullopt;
}

}  // namespace

Result<void> ClothSimulator::add_energy_term(std::shared_ptr<EnergyTerm> term) {
  if (!term) return fail("the energy term is null");
  if (!impl_->integrator->add_energy_term(term)) {
    return fail(std::string(integrator_entry(impl_->options.integrator).name) +
                " cannot take extra energy terms such as " + std::string(term->name()) +
                "; Newton's integrators (implicit-pcg, implicit-multigrid, implicit-direct) can");
  }
  impl_->terms.push_back(std::move(term));
  return {};
}

Result<void> ClothSimulator::set_external_forces(const Eigen::VectorXd& forces) {
  const Eigen::Index size = 3 * static_cast<Eigen::Index>(impl_->model->particle_count());
  if (forces.size() != size) {
    return fail("external forces have " + std::to_string(forces.size()) +
                " entries but the cloth needs " + std::to_string(size));
  }
  if (!all_finite(forces)) return fail("external forces have a non-finite value");
  impl_->external_forces = forces;
  return {};
}

void ClothSimulator::clear_external_forces() {
  impl_->external_forces.reset();
}

Result<void> ClothSimulator::set_state(const ClothState& state) {
  const Eigen::Index size = 3 * static_cast<Eigen::Index>(impl_->model->particle_count());
  if (state.positions.size() != size || state.velocities.size() != size) {
    return fail("state has " + std::to_string(state.positions.size() / 3) +
                " particles but the cloth has " + std::to_string(size / 3));
  }
  if (!all_finite(state.positions) || !all_finite(state.velocities)) {
    return fail("state has a non-finite position or velocity");
  }
  if (!std::isfinite(state.time)) return fail("state has a non-finite time");
  impl_->state = state;
  for (int i = 0; i < impl_->model->particle_count(); ++i) {
    if (impl_->model->pinned[i]) impl_->state.velocities.segment<3>(3 * i).setZero();
  }
  return {};
}

Result<StepReport> ClothSimulator::step(double dt) {
  if (!kTimeStepRange.contains(dt)) return fail(kTimeStepRange.refusal("time step", dt));
  Impl& s = *impl_;
  const auto start = std::chrono::steady_clock::now();
  StepReport report;
  report.substeps = s.options.effective_substeps();
  s.backup.positions = s.state.positions;
  s.backup.velocities = s.state.velocities;
  const double h = dt / report.substeps;
  const Eigen::VectorXd* external = s.external_forces ? &*s.external_forces : nullptr;
  const double start_time = s.state.time;
  s.backup.time = start_time;
  for (int k = 0; k < report.substeps; ++k) {
    s.integrator->step(s.state, h, report, external);
    s.state.time = start_time + (k + 1) * h;  // not summed: no drift over many substeps
  }
  std::optional<std::string> problem = divergence(s.state);
  if (!problem &&
      !(std::isfinite(report.gradient_norm_start) && std::isfinite(report.gradient_norm_end))) {
    // Finite positions from a non-finite gradient are not a result: the step could not be
    // computed (never converged, whatever the comparisons with infinity said).
    problem = "the incremental potential's gradient is not finite";
  }
  if (problem) {
    s.state.positions = s.backup.positions;
    s.state.velocities = s.backup.velocities;
    s.state.time = s.backup.time;
    return fail("the simulation diverged in step " + std::to_string(s.steps + 1) + " (" +
                std::string(integrator_entry(s.options.integrator).name) + ", " +
                std::to_string(report.substeps) + " substep(s) of " + format_number(h) +
                " s): " + *problem);
  }
  ++s.steps;
  report.energy = cloth_energy(*s.model, s.state).total;
  for (const auto& term : s.terms) term->add_to_report(s.state.positions, report);
  report.ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace animkit
