#pragma once
// Contact as part of the implicit step's energy: Incremental Potential Contact (Li et al.,
// SIGGRAPH 2020) for cloth (codimensional IPC, Li et al., SIGGRAPH 2021). Every pair of
// primitives closer than the activation distance dhat (a point and a triangle, two edges, a
// particle and the ground) adds kappa b(d) to g, with b IPC's log barrier on the squared
// distance d (collision/barrier.h), which grows without bound as the pair closes. Newton's
// line search never steps past what continuous collision detection allows (max_step), every
// iterate is intersection-free, so every step is: the barrier is what pushes, CCD is what
// guarantees. Obstacles are fixed triangle meshes, colliders that move on their paths (each
// substep takes their surfaces from their poses at t to their poses at t + h between Newton's
// iterates, as far as CCD allows each time: src/cloth/contact/moving_obstacles.h) and an
// optional ground plane y = height; self-contact covers the cloth's own triangles.
//
// Why IPC and not Offset Geometric Contact (Chen et al. 2025): OGC bounds each vertex's
// displacement inside VBD-style local solves, and on this project's stiff cloth VBD does not
// reach 1e-4 relative gradient at all (docs/stiff-cloth.md: 0% of cotton's steps within 1000
// sweeps), where Newton with multigrid converges every step; IPC rides on that Newton.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/energy_term.h"
#include "animkit/collision/collider.h"
#include "animkit/core/enum_names.h"
#include "animkit/core/result.h"
#include "animkit/core/triangle_mesh.h"
#include "animkit/core/validation.h"

namespace animkit {

struct ContactGeometry;  // src/cloth/contact/contact_candidates.h (internal)

/// How a contact pair's barrier enters Newton's matrix (its gradient is always exact).
enum class BarrierHessian : std::uint8_t {
  /// The exact Hessian of the pair's barrier, projected onto the PSD cone by a 12 x 12
  /// eigendecomposition per pair (IPC, Li et al. 2020, section 4.3).
  projected,
  /// Gauss-Newton: the barrier's curvature along the distance alone, a rank-one matrix that is
  /// PSD by construction (Offset Geometric Contact, Chen et al. 2025, section 3.6); no
  /// eigendecomposition, and Newton's direction stays a descent direction.
  gauss_newton,
  /// Gauss-Newton while Newton's steps run free; the projected exact Hessian for the rest of a
  /// substep once continuous collision detection has frozen a step (cut it below
  /// kFrozenStepFraction of its length), and always for a pair whose gap has collapsed (below
  /// kCollapsedGapFraction of the thickness). Gauss-Newton drops the curvature of the distance
  /// itself, which matters where edges of folded cloth slide across each other: there its
  /// directions run straight into the nearest pair and the steps stall.
  adaptive,
};

/// A step CCD cuts below this fraction of its length is frozen (BarrierHessian::adaptive). On
/// the built-in scenes routine contact cuts Newton's steps to 2e-4 .. 1e-2 of their length (a
/// pair may close 90% of its gap per step); the steps that stalled Gauss-Newton on `fold` were
/// cut to 1e-9 and 4e-15.
inline constexpr double kFrozenStepFraction = 1e-4;

/// A pair closer than this fraction of the thickness takes the projected exact Hessian under
/// BarrierHessian::adaptive even while Newton's steps run free. Gauss-Newton's matrix has no
/// curvature across the distance's gradient, yet there the barrier's term b' hess d grows as
/// 1 / gap: a direction that turns a cloth triangle about a collider's vertex sweeps its
/// plane into that vertex at second order, CCD cuts the step where the gap has fallen to a
/// tenth, and the next direction does the same, down to gaps of 1e-13 m at which Additive CCD
/// walks its million steps per pair (a 25-particle sheet hit by a ball at 10 m/s: 75 Newton
/// iterations and 9 s for one step, against 32 and 0.2 s with this). The exact Hessian costs
/// a 12 x 12 eigendecomposition, paid by these few pairs only.
inline constexpr double kCollapsedGapFraction = 1e-3;

/// Each BarrierHessian's name (scene files, Python), in the enum's order: the only list.
inline constexpr std::array<std::string_view, 3> kBarrierHessianNames = {
    "projected", "gauss_newton", "adaptive"};
inline std::string_view barrier_hessian_name(BarrierHessian hessian) {
  return enum_name(kBarrierHessianNames, hessian);
}
/// The choice called `name`, or none.
inline std::optional<BarrierHessian> barrier_hessian_named(std::string_view name) {
  return enum_named<BarrierHessian>(kBarrierHessianNames, name);
}

/// The smallest gap, as a fraction of the thickness, a contact pair may start at
/// (ContactTerm::check_start): the barrier's gradient grows as the inverse of the gap, and a
/// pair at zero (a particle on a surface, coincident sheets) has none to start from.
inline constexpr double kMinStartGapFraction = 1e-6;

/// A barrier stiffness given by hand (J/m^4): the automatic one for cloth of a gram to a
/// kilogram per particle and a thickness of 0.1 to 10 mm lies between about 1e4 and 1e16.
inline constexpr ParameterRange kContactStiffnessRange{0.0, 1e20};

/// How the contact term acts: the barrier's reach and stiffness, self-contact, CCD's margin.
struct ContactSettings {
  /// dhat, m: the barrier acts on pairs closer than this (the cloth's thickness), > 0.
  double thickness = 2e-3;
  /// kappa, J/m^4; 0 (default) picks it so that a particle of average mass rests on a surface
  /// at about half the thickness under gravity (at least 1 m/s^2 of it), or, in a substep in
  /// which a collider moves at v, under the force m v / h that brings it to that speed when
  /// that is larger (contact_term.cpp).
  double stiffness = 0.0;
  /// The cloth's own points and triangles, and edges, repel each other too.
  bool self_contact = true;
  /// CCD keeps every pair at least this fraction of its distance at the start of a step, so
  /// no iterate gets closer than that to contact: in (0, 1).
  double min_separation = 0.1;
  /// How each pair's barrier Hessian is formed; both keep every iterate intersection-free
  /// (CCD bounds every step whatever the direction).
  BarrierHessian hessian = BarrierHessian::projected;

  /// An Error naming the first invalid field (thickness, stiffness, min_separation), or none.
  std::optional<Error> validate() const;
};

/// The world the cloth meets.
struct ContactObstacles {
  std::vector<TriangleMesh> meshes = {};  ///< fixed surfaces, world space, m; default none
  /// The plane y = height (m), the cloth above it; default none.
  std::optional<double> ground_height = std::nullopt;
  /// Colliders on their motions (planes excepted: give a horizontal floor as ground_height),
  /// each starting where it is placed (Collider::time()); default none. Each substep moves them
  /// to their poses at the substep's end (ClothState::time + h).
  std::vector<Collider> colliders = {};

  /// Every vertex of every mesh, then every collider's contact vertices (its surface's, or a
  /// sphere's centre alone), in order (the indices of the primitives follow).
  int vertex_count() const;
};

/// What the contacts did at the last iterate (for reports and tests).
struct ContactStats {
  int active_pairs = 0;       ///< pairs within dhat
  double min_distance = 0.0;  ///< m, the smallest distance of an active pair (dhat if none)
  int candidate_pairs = 0;    ///< pairs the broad phase gathered
  /// How often the broad phase ran since the term was made: when an iterate or a step left the
  /// region its last pairs cover, not every iteration.
  std::int64_t gathers = 0;
};

/// Where one active pair (closer than the thickness) is closest, for drawing contacts.
struct ContactPoint {
  /// What the cloth touches: a collider's surface (or a fixed mesh), the ground, or itself.
  enum class With : std::uint8_t { collider, ground, self };
  With with = With::collider;  ///< what the cloth touches
  Vec3 cloth = Vec3::Zero();   ///< world space, m: the nearest point of the cloth's primitive
  /// World space, m: the nearest point of the other primitive (a collider's, the ground's
  /// foot point, or the cloth's other primitive for self-contact).
  Vec3 other = Vec3::Zero();
  double distance = 0.0;  ///< m, |cloth - other|, in [0, thickness)
};

/// Incremental Potential Contact as an energy term: barriers between close pairs, with CCD
/// bounding every step (see the comment at the top of contact.h, and docs/contact.md).
class ContactTerm final : public EnergyTerm {
 public:
  /// Fails on invalid settings or obstacles, or a model without triangles.
  static Result<std::shared_ptr<ContactTerm>> create(std::shared_ptr<const ClothModel> model,
                                                     const ContactSettings& settings,
                                                     ContactObstacles obstacles);
  ~ContactTerm() override;

  std::string_view name() const override { return "contact"; }
  void prepare(const ClothState& state, double h) override;
  void advance(Eigen::VectorXd& x) override;
  void update(const Eigen::VectorXd& x) override;
  double max_step(const Eigen::VectorXd& x, const Eigen::VectorXd& step) override;
  void add_to_report(const Eigen::VectorXd& x, StepReport& report) const override;
  double value(const Eigen::VectorXd& x) const override;
  double difference(const Eigen::VectorXd& x, const Eigen::VectorXd& step) const override;
  void add_gradient(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) const override;
  void add_hessian(const Eigen::VectorXd& x, bool projected,
                   std::vector<HessianBlock>& blocks) const override;
  bool hessian_ignores_projection() const override { return true; }

  /// False while a collider is short of its pose at the substep's end (CCD held it back).
  bool settled() const override;
  bool gaps_settled(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) const override;
  /// Fails, naming the particles and the obstacle, when the cloth at x cannot start against
  /// the obstacles where they are now: with self-contact, a thickness above the cloth's mean
  /// edge length (its own neighbours would repel); a pair closer than kMinStartGapFraction of
  /// the thickness (the barrier is infinite at contact); an edge of the cloth through an
  /// obstacle's triangle, an obstacle's edge through the cloth, or, with self-contact, the
  /// cloth through itself (no barrier acts between crossing primitives, so such a start would
  /// run on crossed). IPC keeps a start that passes intersection-free.
  Result<void> check_start(const Eigen::VectorXd& x) const;

  /// Drives collider `index` (of ContactObstacles::colliders, in order) by hand from now on
  /// (e.g. the viewer's mouse): the next substep moves it from where it is to `target` (world
  /// space) with the same guarantee, and it stays there, its motion no longer followed, until
  /// the next target. Errors: no such collider, a non-finite position, a rotation that is not
  /// a unit quaternion.
  Result<void> move_collider(std::size_t index, const RigidPose& target);
  /// The colliders, in order (their shapes, names and motions; poses: collider_pose()).
  const std::vector<Collider>& colliders() const;
  /// The pose collider `index` last reached (its pose at the end of the last settled substep).
  const RigidPose& collider_pose(std::size_t index) const;
  /// Every collider's surface vertices where they are now, world, m: x, y, z each, in
  /// colliders_obj()'s vertex order (io/collider_export.h): a colliders.pc2 frame.
  Eigen::VectorXd collider_points() const;
  /// Every obstacle vertex (ContactObstacles::vertex_count() of them) where it is now, world,
  /// m, 3 each.
  const Eigen::VectorXd& obstacle_positions() const;
  /// The same vertices where they were at the substep's start: the difference from
  /// obstacle_positions() is how far the obstacles moved in the substep so far (what friction
  /// slides against).
  const Eigen::VectorXd& obstacle_start_positions() const;

  /// The barrier stiffness in use (J/m^4): this substep's when automatic (ContactSettings).
  double stiffness() const;
  /// Contacts at the last iterate.
  ContactStats stats(const Eigen::VectorXd& x) const;
  /// The closest points of every pair active at x among those the last update() or
  /// max_step() gathered, in the pairs' order (stats(x).active_pairs of them). `out` is
  /// resized; its capacity is reused.
  void contact_points(const Eigen::VectorXd& x, std::vector<ContactPoint>& out) const;

  /// The settings it was created with. This, ground_height() and geometry() are what the
  /// friction term (friction.h) lags from the same contacts.
  const ContactSettings& settings() const;
  /// The ground plane's height y (m), or none without a ground.
  std::optional<double> ground_height() const;
  /// The cloth's and the obstacles' primitives (an internal type of src/cloth/contact/).
  const ContactGeometry& geometry() const;

 private:
  struct Impl;
  explicit ContactTerm(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace animkit
