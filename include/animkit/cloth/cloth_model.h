#pragma once
// Mass-spring cloth (docs/implicit-step.md): an editable description, the immutable model built
// from it once, and the state (positions, velocities) that integrators advance.
#include <array>
#include <optional>
#include <vector>

#include "animkit/core/result.h"
#include "animkit/core/types.h"

namespace animkit {

/// One particle of a ClothDesc: its initial position and velocity, mass, and whether pinned.
struct ParticleDesc {
  Vec3 position = Vec3::Zero();  ///< world space, scene units
  Vec3 velocity = Vec3::Zero();  ///< world space, units per second
  double mass = 1.0;             ///< > 0; the lab's slider range is 0.5..10
  bool pinned = false;           ///< pinned particles never move
};

/// One spring of a ClothDesc, joining two particles.
struct SpringDesc {
  /// First particle's index, in [0, particle count).
  int a = 0, b = 0;           ///< particle indices, distinct
  double rest_length = -1.0;  ///< > 0, or negative: the distance of a and b in the description
  double stiffness = 100.0;   ///< k > 0 (force per unit length); lab range 10..300, default 100
};

/// A bending element over three or four particles with constant weights w:
/// E = 1/2 stiffness |sum_i w_i x_i|^2, a quadratic bending energy with a constant Hessian
/// (Bergou et al. 2006, "A quadratic bending model for inextensible surfaces"; derivatives in
/// bend_energy.h). The weights sum to zero, so translations cost nothing.
/// - The grid's element (line_bend): three particles a, b, c along a line of the sheet, b in the
///   middle, w = (1, -2, 1): the squared discrete curvature of the line. For a sheet with
///   bending stiffness B (N m) and spacing s, stiffness = B / s^2 gives 1/2 B kappa^2 per unit
///   area (see material.h).
/// - A mesh's element (mesh_cloth.h): the four particles around an interior edge with Bergou's
///   cotangent weights.
struct BendDesc {
  /// Distinct particle indices; the last one -1 for a three-particle bend.
  std::array<int, 4> particles{-1, -1, -1, -1};
  /// w_i, finite, summing to zero (to rounding); 0 in an unused slot. Dimensionless.
  std::array<double, 4> weights{};
  double stiffness = 0.0;  ///< c, N/m, in kStiffnessRange
};

/// The grid's line element over a, b (the middle one), c: weights (1, -2, 1).
inline BendDesc line_bend(int a, int b, int c, double stiffness) {
  return {{a, b, c, -1}, {1.0, -2.0, 1.0, 0.0}, stiffness};
}

/// Editable description of a cloth.
struct ClothDesc {
  std::vector<ParticleDesc> particles;  ///< at least one; springs and bends index into it
  std::vector<SpringDesc> springs;      ///< may be empty
  std::vector<BendDesc> bends;  ///< may be empty (the lab's cloth bends through its springs)
  /// Surface triangles over the particles, for drawing and export, and for the energy terms
  /// that need a surface (air drag, contact); the elastic forces are the springs' and bends'.
  /// May be empty.
  std::vector<std::array<int, 3>> triangles;
  double gravity = 0.3;  ///< acceleration along -y (units/s^2); lab range 0.1..1, default 0.3
  /// Spring dashpot coefficient c: each spring also pulls with c (v_b - v_a).u along its axis u
  /// (the lab's damping). >= 0; lab range 0.1..10, default 0.2.
  double damping = 0.2;

  /// The first problem with this description, or nothing when it can be built.
  std::optional<Error> validate() const;
};

/// Immutable runtime model: flat arrays, rest lengths resolved.
struct ClothModel {
  std::vector<double> mass;  ///< per particle
  std::vector<char> pinned;  ///< per particle, 0 or 1
  /// The described springs, then one spring of stiffness 0 for each pair a bend couples that
  /// no spring joins: it carries the bend's Hessian blocks (solvers store one 3x3 block per
  /// spring), no force and no dashpot.
  std::vector<std::array<int, 2>> springs;
  std::vector<double> rest_length;  ///< per spring
  std::vector<double> stiffness;    ///< per spring; 0 only for the bends' coupling springs
  /// Per bend: its 3 or 4 particles (an unused last slot -1), their weights and stiffness.
  std::vector<std::array<int, 4>> bends;
  std::vector<std::array<double, 4>> bend_weights;  ///< per bend: w_i, 0 in an unused slot
  std::vector<double> bend_stiffness;               ///< per bend: c, N/m
  /// Per bend: the springs joining its particle pairs in kBendPairs order (bend_energy.h),
  /// which hold its Hessian blocks; -1 for a pair with an unused slot.
  std::vector<std::array<int, 6>> bend_springs;
  std::vector<std::array<int, 3>> triangles;  ///< ClothDesc::triangles, as described
  double gravity = 0.3;  ///< ClothDesc::gravity: acceleration along -y (units/s^2)
  double damping = 0.2;  ///< ClothDesc::damping: the springs' dashpot coefficient c

  /// Number of particles N.
  int particle_count() const { return static_cast<int>(mass.size()); }
  /// Number of springs, the bends' coupling springs included.
  int spring_count() const { return static_cast<int>(springs.size()); }
  /// Number of bending elements.
  int bend_count() const { return static_cast<int>(bends.size()); }
};

/// Positions and velocities of every particle, 3 doubles each, particle-major
/// (x0 y0 z0 x1 y1 z1 ...), the layout the solvers' vectors use.
struct ClothState {
  Eigen::VectorXd positions;   ///< 3N, world space, scene units
  Eigen::VectorXd velocities;  ///< 3N, world space, units per second
  /// The simulated time this state is at, s (default 0: where a scene starts; any finite
  /// value). ClothSimulator advances it by every substep's h; energy terms whose world moves
  /// with time (colliders on a path, gusts) read it in EnergyTerm::prepare as the substep's start.
  double time = 0.0;

  /// Particle i's position (a copy), 0 <= i < N.
  Vec3 position(int i) const { return positions.segment<3>(3 * i); }
  /// Particle i's velocity (a copy), 0 <= i < N.
  Vec3 velocity(int i) const { return velocities.segment<3>(3 * i); }
};

/// A cloth built from its description: the model and its initial state.
struct BuiltCloth {
  ClothModel model;  ///< the immutable model
  ClothState state;  ///< the described positions and velocities (pinned particles at rest), time 0
};
/// Validates `desc` and builds the model and its initial state; the error names the first
/// problem (ClothDesc::validate).
Result<BuiltCloth> build_cloth(const ClothDesc& desc);

/// Energies of a state, in the model's units (J with m, kg and s). Damping removes total
/// energy over time.
struct ClothEnergy {
  /// Kinetic energy, 1/2 sum m |v|^2.
  double kinetic = 0.0, elastic = 0.0, gravitational = 0.0, total = 0.0;
  /// \var elastic
  /// Elastic energy: the springs' sum 1/2 k (l - L)^2 plus the bends' energy (bend_energy.h).
  /// \var gravitational
  /// Gravitational energy, sum m g y (zero at y = 0).
  /// \var total
  /// kinetic + elastic + gravitational.
};
/// The energies of `state` (of `model`'s size).
ClothEnergy cloth_energy(const ClothModel& model, const ClothState& state);

}  // namespace animkit
