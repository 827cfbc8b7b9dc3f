#pragma once
// Implicit Euler by Vertex Block Descent (Chen, Macklin, Wang, Kaufman, Kim, Yuksel:
// "Vertex Block Descent", SIGGRAPH 2024). It minimizes the same incremental potential g as
// Newton (incremental_potential.h) by block coordinate descent: one iteration is a sweep over
// the particles, colour by colour (graph_coloring.h); each free particle i, with all others
// fixed, takes one 3x3 Newton step on its local energy g_i (the terms of g that involve x_i:
// inertia, incident springs and their dashpots, incident bends),
//   f_i = -dg/dx_i,  H_i = d2g/dx_i^2 (spring blocks projected, so H_i >= m_i/h^2 I is SPD),
//   x_i += alpha H_i^-1 f_i                                           (VBD eq. 10)
// with alpha backtracked from 1 until g_i satisfies Armijo (VBD's own update has no line search;
// this guard is what makes g decrease at every sweep, which the plain step does not promise
// where springs are compressed or strongly nonlinear). Particles of one colour share no element,
// so their updates are independent and the sweep's decrease of g is the sum of the local ones.
// The stopping test is Newton's: |grad g| <= max(tolerance |grad g(y)|, gradient floor).
#include <memory>
#include <vector>

#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/graph_coloring.h"
#include "animkit/cloth/incremental_potential.h"
#include "animkit/cloth/integrator.h"
#include "animkit/cloth/integrator_settings.h"
#include "animkit/cloth/step_report.h"

namespace animkit {

/// Advances a cloth by implicit Euler steps solved by VBD sweeps from x = y. The colouring and
/// each particle's incident springs and bends are built once per model; nothing allocates in
/// the sweeps. In the StepReport, ms_linear_solve is the sweeps' time, ms_gradient the stopping
/// tests', ms_line_search the Chebyshev check's; newton_iterations counts sweeps and
/// line_search_steps the local backtracking halvings. Each IterationRecord's `decrease` is the
/// sweep's g(x_{k+1}) - g(x_k) summed from the local differences, its `slope` the sum of the
/// local slopes grad_i g . dx_i as the sweep met them (negative), `alpha` the Chebyshev weight
/// (1 without acceleration).
class VertexBlockDescent final : public ClothIntegrator {
 public:
  /// Integrates `model` (shared: kept alive by this integrator) with the valid `options`;
  /// colours the particles and gathers their incident springs and bends once.
  VertexBlockDescent(std::shared_ptr<const ClothModel> model, const VbdSettings& options);

  void step(ClothState& state, double h, StepReport& report,
            const Eigen::VectorXd* external_forces = nullptr) override;

  /// The particles' colouring the sweeps follow (color_cloth_particles() of the model).
  const GraphColoring& coloring() const { return coloring_; }

 private:
  struct SweepTotals {
    double decrease = 0.0, slope = 0.0;
    int backtracks = 0, moved = 0;
  };
  struct IncidentSpring {
    int spring, other;
  };
  struct IncidentBend {
    int bend, slot;  // slot: the particle's place (0..3) in the bend
  };
  void sweep(SweepTotals& totals);
  void update_particle(int i, SweepTotals& totals);
  double local_difference(int i, const Vec3& step) const;
  bool chebyshev(int iteration, double& omega, IterationRecord& record, StepReport& report);

  // Shared and immutable: the reference below stays valid however this integrator moves.
  std::shared_ptr<const ClothModel> model_owner_;
  const ClothModel& model_;
  VbdSettings options_;
  IncrementalPotential potential_;
  GraphColoring coloring_;
  // Free particles grouped by colour: colour c is sweep_particles_[sweep_offsets_[c], [c + 1]).
  std::vector<int> sweep_particles_, sweep_offsets_;
  // The sweep's parallel chunks: colour c's are chunk_totals_[chunk_offsets_[c], [c + 1]),
  // kSweepChunk particles each (small enough that a colour of a mid-size cloth still splits).
  static constexpr int kSweepChunk = 64;
  std::vector<int> chunk_offsets_;
  std::vector<SweepTotals> chunk_totals_;
  // Per particle, its incident springs of stiffness > 0 and its bends (compressed rows).
  std::vector<int> spring_start_, bend_start_;
  std::vector<IncidentSpring> incident_springs_;
  std::vector<IncidentBend> incident_bends_;
  // Per incident spring entry, written by update_particle() for local_difference(): the
  // spring's length and dashpot displacement at the particle's current x. Each entry belongs
  // to one particle, so the particles of a colour never write the same one.
  std::vector<double> incident_length_, incident_axial_;
  double inv_h2_ = 0.0, dashpot_ = 0.0;  // 1/h^2 and c/h for the current substep
  Eigen::VectorXd x_, gradient_, previous_, before_sweep_, chebyshev_step_;
};

}  // namespace animkit
