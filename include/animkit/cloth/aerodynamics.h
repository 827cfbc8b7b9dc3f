#pragma once
// Wind and air drag on the cloth's triangles, as an energy term of the implicit step
// (energy_term.h), so it is taken implicitly and stays stable at any time step.
//
// Each triangle (area A, unit normal n, both frozen at x_n like the dashpots' axes) moving with
// the mean velocity of its corners v = sum_i (x_i - x_n,i) / (3h) through air moving at w feels
// the quadratic drag of a flat plate (Hoerner, "Fluid-Dynamic Drag", 1965): with r = v - w,
//   F = -1/2 rho A [C_n |r.n| (r.n) n + C_t |r_t| r_t],   r_t = r - (r.n) n,
// pressure drag along the normal and skin friction in the plane, a third on each corner.
// A plate inclined to the wind gets a force along its normal, i.e. lift as well as drag.
// F is minus the gradient of the convex, C^2 potential
//   D(x) = h rho A / 6 [C_n |r.n|^3 + C_t |r_t|^3]
// (d/dx_i of |s|^3 / 3 is |s| s ds/dx_i and dr/dx_i = I / (3h)), whose Hessian
//   rho A / (18 h) [2 C_n |r.n| n n^T + C_t (|r_t| P + r_t r_t^T / |r_t|)],   P = I - n n^T,
// couples the triangle's three corners: every block (i, j) is that 3x3 matrix.
//
// The wind w(x, t) is a constant velocity plus gusts that travel with it: the gust factor
// s(t - (x . u) / |w0|), u the wind's direction, with s a fixed sum of incommensurate
// sinusoids in [0, 1], so a flag's cloth meets each gust at its pinned edge first.
// The wind is evaluated at each substep's end (state.time + h), as implicit Euler does.
#include <memory>
#include <optional>
#include <vector>

#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/energy_term.h"
#include "animkit/core/result.h"
#include "animkit/core/types.h"

namespace animkit {

/// The wind: a steady velocity plus gusts that travel downwind with it.
struct WindSettings {
  Vec3 velocity = Vec3::Zero();  ///< m/s, world space: the steady wind (zero: still air)
  /// m/s, world space: the gusts' extra velocity at their peak, added to `velocity`.
  Vec3 gust = Vec3::Zero();
  double gust_frequency = 0.5;  ///< Hz, > 0: how often gusts come

  /// The wind velocity at world point x at time t (s).
  Vec3 at(const Vec3& x, double t) const;
};

/// Settings of the air term: the wind and the air's density and drag coefficients.
struct AirSettings {
  WindSettings wind;              ///< the air's velocity field (still air by default)
  double density = 1.2;           ///< kg/m^3 (air at 20 C), >= 0; 0 turns the term off
  double normal_drag = 1.2;       ///< C_n, flat-plate pressure drag coefficient, >= 0
  double tangential_drag = 0.02;  ///< C_t, skin friction coefficient, >= 0

  /// The first invalid setting (a NaN, a negative coefficient, a non-positive gust frequency).
  std::optional<Error> validate() const;
};

/// Quadratic flat-plate drag of the moving air on the cloth's triangles, as an energy term of
/// the implicit step (see the comment at the top of aerodynamics.h).
class AirTerm final : public EnergyTerm {
 public:
  /// Fails when the settings are invalid or the model has no triangles to catch the air.
  static Result<std::shared_ptr<AirTerm>> create(const ClothModel& model,
                                                 const AirSettings& settings);

  std::string_view name() const override { return "air"; }
  void prepare(const ClothState& state, double h) override;
  double value(const Eigen::VectorXd& x) const override;
  void add_gradient(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) const override;
  void add_hessian(const Eigen::VectorXd& x, bool projected,
                   std::vector<HessianBlock>& blocks) const override;
  bool hessian_ignores_projection() const override { return true; }

  /// The time the last prepared substep ends at (s since the start).
  double time() const { return time_; }

 private:
  AirTerm(const ClothModel& model, const AirSettings& settings);
  // The relative velocity r of triangle t at x, split along its normal: r.n and r_t.
  void relative_velocity(const Eigen::VectorXd& x, int t, double& normal, Vec3& tangential) const;

  std::vector<std::array<int, 3>> triangles_;
  AirSettings settings_;
  double time_ = 0.0, h_ = 0.0;
  Eigen::VectorXd x_start_;
  std::vector<Vec3> normal_, wind_;  // per triangle, frozen at x_n
  std::vector<double> area_;
};

}  // namespace animkit
