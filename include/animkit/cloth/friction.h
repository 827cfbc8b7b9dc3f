#pragma once
// Friction as part of the implicit step's energy: IPC's lagged, smoothed Coulomb model (Li et
// al., "Incremental Potential Contact", SIGGRAPH 2020, section 5; for cloth, Li et al.,
// "Codimensional Incremental Potential Contact", SIGGRAPH 2021). For every contact pair active
// at the substep's start x_n (the contact term's pairs: point-triangle, edge-edge, ground), the
// normal force magnitude lambda, the closest points' weights w and a tangent basis T (3x2) are
// frozen ("lagged"); then
//   D(x) = sum_pairs mu lambda f0(|u|),   u = T^T sum_i w_i (dx_i - do_i),
// dx_i = x_i - x_n,i the pair's cloth vertices' displacement over the substep and do_i the
// obstacle's own (zero for static obstacles), and f0 IPC's C^1 (here C^2) smoothing of |u|
// (eq. 16) with eps_u = eps_v h:
//   f0(y) = -y^3 / (3 eps_u^2) + y^2 / eps_u + eps_u / 3  (y < eps_u),  y  (y >= eps_u).
// Its gradient is the friction force: -mu lambda f1(|u|) u/|u| through T, with f1 = f0' rising
// from 0 to 1 over sliding speeds [0, eps_v], so a pair slides against the full Coulomb force
// mu lambda beyond eps_v and "sticks" (creeps slower than eps_v) below. With lambda, w and T
// frozen, D is convex in x (f0 is convex and increasing, |.| convex, u linear), so its exact
// Hessian is already PSD: no projection is needed.
//
// Lagging passes (IPC section 5): after Newton converges, lambda, w and T can be re-lagged at
// the converged x and the step solved again, until they stop changing (then Newton's stopping
// test holds at once after a re-lag) or the passes run out. Default: one pass (lagged at x_n).
#include <memory>
#include <optional>
#include <vector>

#include "animkit/cloth/contact.h"
#include "animkit/cloth/energy_term.h"
#include "animkit/core/result.h"

namespace animkit {

/// The friction coefficients per obstacle, ground and self-contact, and how friction is lagged.
struct FrictionSettings {
  /// Coulomb coefficient mu between the cloth and each obstacle mesh, in the order of
  /// ContactObstacles::meshes (colliders' own ColliderDesc::friction); dimensionless, finite,
  /// >= 0 (0 disables friction on that mesh). Must list every mesh.
  std::vector<double> obstacles;
  /// mu between the cloth and the ground plane: finite, >= 0, default 0.3.
  double ground = 0.3;
  /// mu between two parts of the cloth (self-contact): finite, >= 0, default 0.3.
  double self = 0.3;
  /// eps_v, m/s: sliding slower than this counts as sticking (IPC's smoothing velocity);
  /// finite, > 0, default 1e-3 (IPC's default relative to a 1 m scene).
  double smoothing_velocity = 1e-3;
  /// Lagging passes per substep, >= 1, default 1: the normal forces and bases are lagged at
  /// x_n, then re-lagged at each converged x up to this many solves in all.
  int max_passes = 1;

  /// The first problem, e.g. "friction on obstacle 2 must be >= 0, got -1".
  std::optional<Error> validate() const;
};

/// What friction holds at the last lag (for reports and tests).
struct FrictionStats {
  int point_triangle_pairs = 0;   ///< lagged point-triangle pairs with mu > 0
  int edge_edge_pairs = 0;        ///< lagged edge-edge pairs with mu > 0
  int ground_pairs = 0;           ///< lagged particle-ground pairs with mu > 0
  double normal_force_sum = 0.0;  ///< N, >= 0: the sum of lambda over those pairs
  int passes = 0;                 ///< lagging passes so far in the current substep, >= 0
};

/// IPC's lagged, smoothed Coulomb friction on the contact term's pairs, as an energy term
/// (see the comment at the top of friction.h).
class FrictionTerm final : public EnergyTerm {
 public:
  /// Friction on the pairs of `contact` (add it to the simulator after `contact`). Fails on
  /// invalid settings or a list of obstacle coefficients that does not match the meshes.
  static Result<std::shared_ptr<FrictionTerm>> create(std::shared_ptr<const ContactTerm> contact,
                                                      const FrictionSettings& settings);
  ~FrictionTerm() override;

  std::string_view name() const override { return "friction"; }
  /// Lags lambda, w and T at x_n over h.
  void prepare(const ClothState& state, double h) override;
  /// Re-lags at a converged x while passes remain (see the header's comment).
  bool relag(const Eigen::VectorXd& x) override;
  double value(const Eigen::VectorXd& x) const override;
  double difference(const Eigen::VectorXd& x, const Eigen::VectorXd& step) const override;
  void add_gradient(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) const override;
  /// The exact Hessian, PSD as it is (`projected` changes nothing).
  void add_hessian(const Eigen::VectorXd& x, bool projected,
                   std::vector<HessianBlock>& blocks) const override;
  bool hessian_ignores_projection() const override { return true; }

  /// The pairs and normal forces of the last lag, and the passes so far.
  FrictionStats stats() const;

 private:
  struct Impl;
  explicit FrictionTerm(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace animkit
