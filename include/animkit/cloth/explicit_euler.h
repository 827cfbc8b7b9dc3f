#pragma once
// Explicit (symplectic) Euler, the lab's starting point (docs/implicit-step.md): per substep of
// length h, v += h a(x, v), then x += h v. The lab runs 1000 substeps per frame to stay stable.
#include <Eigen/Core>
#include <memory>

#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/integrator.h"

namespace animkit {

/// Spring, dashpot and gravity forces on every particle at (x, v), into `forces` (3N).
void cloth_forces(const ClothModel& model, const Eigen::VectorXd& positions,
                  const Eigen::VectorXd& velocities, Eigen::VectorXd& forces);

/// Explicit (symplectic) Euler: per substep v += h a(x, v), then x += h v. Takes no energy
/// terms.
class ExplicitEuler final : public ClothIntegrator {
 public:
  /// Integrates `model`, which it shares (keeps alive).
  explicit ExplicitEuler(std::shared_ptr<const ClothModel> model);

  /// One substep of h, from `state` into `state`. `external_forces` (3N, may be null) are added
  /// to the forces.
  void step(ClothState& state, double h, StepReport& report,
            const Eigen::VectorXd* external_forces = nullptr) override;

 private:
  // Shared and immutable: the reference below stays valid however this integrator moves.
  std::shared_ptr<const ClothModel> model_owner_;
  const ClothModel& model_;
  Eigen::VectorXd forces_;
};

}  // namespace animkit
