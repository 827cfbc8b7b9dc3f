#pragma once
// What every cloth integrator does: advance a state by one substep of h seconds, adding what it
// did to a StepReport. ClothSimulator owns one, made by make_integrator() from the settings.
#include <Eigen/Core>
#include <memory>

#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/energy_term.h"
#include "animkit/cloth/integrator_settings.h"
#include "animkit/cloth/step_report.h"

namespace animkit {

/// A cloth integrator: advances a ClothState by one substep at a time.
class ClothIntegrator {
 public:
  virtual ~ClothIntegrator() = default;
  /// One substep of h > 0 from `state` into `state`. `external_forces` (3N, may be null) act
  /// like gravity, constant over the substep.
  virtual void step(ClothState& state, double h, StepReport& report,
                    const Eigen::VectorXd* external_forces) = 0;
  /// Adds an energy term to the potential it minimizes; false if it cannot take one (see
  /// ClothSimulator::add_energy_term).
  virtual bool add_energy_term(std::shared_ptr<EnergyTerm> /*term*/) { return false; }
};

/// The integrator `settings` selects, for `model` (shared: many integrators and states may use
/// one model, which never changes). The settings must be valid.
std::unique_ptr<ClothIntegrator> make_integrator(std::shared_ptr<const ClothModel> model,
                                                 const IntegratorSettings& settings);

}  // namespace animkit
