#pragma once
// A cloth scene as data: the sheet, what it meets (colliders, a ground, the air), the solver
// and the run's length. The CLI's options, a JSON scene file (io/cloth_scene_file.h) and the
// built-in scenes (scene/cloth_scenes.h) all describe a run as one ClothWorldDesc;
// build_cloth_world() turns it into a simulator with its energy terms, the one place where
// contact and air are wired to a cloth.
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "animkit/cloth/aerodynamics.h"
#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/contact.h"
#include "animkit/cloth/friction.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/mesh_cloth.h"
#include "animkit/collision/collider.h"
#include "animkit/core/result.h"

namespace animkit {

/// The infinite ground plane y = height: the cloth stays above it.
struct GroundDesc {
  double height = 0.0;    ///< world y, m, finite
  double friction = 0.3;  ///< Coulomb coefficient mu between cloth and ground, finite, >= 0
};

/// A whole cloth scene as data: the sheet, what it meets, the solver and the run's length.
struct ClothWorldDesc {
  /// The sheet: a grid (the lab's by default) or a cloth cut from a triangle mesh.
  std::variant<GridClothOptions, MeshClothOptions> cloth = GridClothOptions{};
  /// The material preset's name when the sheet's material came from one (for reports), else
  /// empty.
  std::string material_name;
  std::vector<ColliderDesc> colliders;  ///< solid, possibly moving; names distinct
  std::optional<GroundDesc> ground;     ///< none by default (the lab's cloth touches nothing)
  /// Contact settings, used when there is a collider or a ground.
  ContactSettings contact;
  /// Coulomb coefficient mu between two parts of the cloth (self-contact), finite, >= 0.
  double self_friction = 0.3;
  /// Friction's lagging passes per substep (FrictionSettings::max_passes), >= 1.
  int friction_passes = 1;
  std::optional<AirSettings> air;  ///< wind and air drag; none by default (still, no drag)
  SimulationOptions simulation;    ///< the integrator and its settings
  /// The scene asked for the fastest integrator ("auto"): a run measures them on its first
  /// steps (choose_integrator) and takes the winner; until then `simulation` holds the
  /// default's settings (with the scene's tolerance).
  bool choose_integrator = false;
  double time_step = 1.0 / 60.0;   ///< s per frame, in kTimeStepRange (the lab's 1/60)
  int frames = 300;                ///< frames to simulate, in [1, kMaxWorldFrames]

  /// Whether the cloth has something to touch: a collider or a ground (then contact is on).
  bool has_contact() const { return !colliders.empty() || ground.has_value(); }
  /// Whether the sheet is physical: a material (the grid's or the mesh's) gives its masses and
  /// stiffnesses, rather than the lab's per-particle parameters.
  bool is_physical() const;
  /// Whether a run that names no solver of its own takes use_fast_settings(): a physical
  /// sheet or one with something to touch. The lab's cloth keeps the lab's solver (CG, 1e-6).
  bool fast_by_default() const { return has_contact() || is_physical(); }
  /// Friction's settings: each collider's and the ground's coefficient, self_friction (0
  /// without self-contact), the passes.
  FrictionSettings friction_settings() const;
  /// Contact with some nonzero friction coefficient.
  bool has_friction() const;
  /// The first problem: the sheet's options, a collider's, the ground's, contact or air
  /// settings, the solver's, a time step or frame count out of range. Building can still fail
  /// on what needs the built cloth (a particle starting inside a collider).
  std::optional<Error> validate() const;
};

/// Largest frame count a world runs: a run still ends.
constexpr int kMaxWorldFrames = 1'000'000;

/// Newton's iteration cap with contact, when the settings leave theirs at its default: an impact
/// takes many more iterations than a free cloth, since continuous collision detection shortens the
/// steps while new parts of the cloth arrive at a collider.
constexpr int kContactNewtonIterations = 300;

/// The fast settings (docs/contact.md), which a physical sheet or one with contact takes unless
/// its solver is named (fast_by_default): Newton with the multigrid preconditioner to
/// 1e-4 relative gradient or IPC's velocity stop at 1e-3 (NewtonSettings::velocity_tolerance),
/// CG to a fixed 10% residual (linear_forcing), the adaptive barrier Hessian
/// (BarrierHessian::adaptive) and, while contact or wind join a step, the projected spring
/// Hessian at once (HessianProjection::with_terms). Every iterate stays intersection-free as
/// with IPC's own settings (projected Hessian, 1e-4 alone), which remain the reference they
/// are measured against: on drape-sphere at 41 x 41, 1.85 times faster over the run, every
/// step within 18 mm of the reference's from the same state (median 0.03 mm;
/// docs/contact.md).
void use_fast_settings(ClothWorldDesc& world);

/// IPC's own settings, the reference quality mode the fast ones are measured against: Newton
/// with the multigrid preconditioner to 1e-4 relative gradient alone, CG's adaptive forcing,
/// each pair's exact barrier Hessian projected onto the PSD cone (BarrierHessian::projected).
void use_reference_contact_settings(ClothWorldDesc& world);

/// A built world: the simulator (with contact, friction and air terms added) and the colliders as
/// they stand at time 0 (for drawing and export).
struct ClothWorld {
  ClothSimulator simulator;         ///< the cloth, its integrator and energy terms
  std::vector<Collider> colliders;  ///< built from ClothWorldDesc::colliders, in order, at time 0
  std::shared_ptr<ContactTerm> contact;  ///< null without colliders or ground
  /// Null without contact, or when every friction coefficient is 0.
  std::shared_ptr<FrictionTerm> friction;
  std::shared_ptr<AirTerm> air;  ///< null in still air
};

/// The sheet's description (grid or mesh), validated.
Result<ClothDesc> build_world_cloth(const ClothWorldDesc& desc);

/// Validates and builds everything. Errors name the first problem, including a particle that
/// starts inside a collider or on or below the ground.
Result<ClothWorld> build_cloth_world(const ClothWorldDesc& desc);
/// The same around a given sheet in place of desc.cloth's (e.g. the viewer's, with pins the
/// user toggled); desc.cloth is not used.
Result<ClothWorld> build_cloth_world(const ClothWorldDesc& desc, const ClothDesc& cloth);

}  // namespace animkit
