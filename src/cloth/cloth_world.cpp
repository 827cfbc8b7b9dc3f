#include "animkit/cloth/cloth_world.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "animkit/cloth/parameter_ranges.h"
#include "animkit/core/quote.h"
#include "animkit/core/validation.h"

namespace animkit {

std::optional<Error> ClothWorldDesc::validate() const {
  if (const auto* grid = std::get_if<GridClothOptions>(&cloth)) {
    if (auto error = grid->validate()) return error;
  }
  if (auto error = validate_colliders(colliders)) return error;
  for (const ColliderDesc& c : colliders) {
    if (std::holds_alternative<PlaneShape>(c.shape)) {
      return Error{"collider " + quote_input(c.name) +
                   ": contact takes no plane collider; give a floor as the scene's ground"};
    }
  }
  if (ground) {
    if (!kCoordinateRange.contains(ground->height))
      return Error{kCoordinateRange.refusal("the ground's height", ground->height)};
    if (!kFrictionRange.contains(ground->friction))
      return Error{kFrictionRange.refusal("the ground's friction", ground->friction)};
  }
  if (has_contact()) {
    if (auto error = contact.validate()) return error;
    if (auto error = friction_settings().validate()) return error;
  }
  if (air) {
    if (auto error = air->validate()) return error;
  }
  if (auto error = simulation.validate()) return error;
  if (!kTimeStepRange.contains(time_step))
    return Error{kTimeStepRange.refusal("the time step (s)", time_step)};
  if (frames < 1 || frames > kMaxWorldFrames) {
    return Error{"frames must be between 1 and " + std::to_string(kMaxWorldFrames) + ", got " +
                 std::to_string(frames)};
  }
  return std::nullopt;
}

FrictionSettings ClothWorldDesc::friction_settings() const {
  FrictionSettings friction;
  for (const ColliderDesc& c : colliders) friction.obstacles.push_back(c.friction);
  friction.ground = ground ? ground->friction : 0.0;
  friction.self = contact.self_contact ? self_friction : 0.0;
  friction.max_passes = friction_passes;
  return friction;
}

bool ClothWorldDesc::has_friction() const {
  const FrictionSettings f = friction_settings();
  return has_contact() &&
         (f.ground > 0.0 || f.self > 0.0 ||
          std::any_of(f.obstacles.begin(), f.obstacles.end(), [](double mu) { return mu > 0.0; }));
}

Result<ClothDesc> build_world_cloth(const ClothWorldDesc& desc) {
  if (const auto* grid = std::get_if<GridClothOptions>(&desc.cloth)) {
    if (auto error = grid->validate()) return fail(error->message);
    return make_grid_cloth(*grid);
  }
  return make_mesh_cloth(std::get<MeshClothOptions>(desc.cloth));
}

namespace {

// The contact term over the colliders' surfaces at time 0 and the ground; refuses a cloth
// that starts inside a collider, on or below the ground, touching or through a collider or
// itself, or a self-contact thickness beyond its edges (ContactTerm::check_start).
Result<std::shared_ptr<ContactTerm>> make_contact(const ClothWorldDesc& desc,
                                                  const ClothSimulator& sim,
                                                  const std::vector<Collider>& colliders) {
  const Eigen::VectorXd& x = sim.state().positions;
  if (auto inside = find_particle_inside(x, colliders)) return fail(inside->message);
  ContactObstacles obstacles;
  if (desc.ground) {
    obstacles.ground_height = desc.ground->height;
    for (int i = 0; i < sim.model().particle_count(); ++i) {
      if (sim.state().position(i).y() <= desc.ground->height)
        return fail("particle " + std::to_string(i) + " starts on or below the ground");
    }
  }
  obstacles.colliders = colliders;  // moved by the contact term along their motions
  auto term = ContactTerm::create(std::make_shared<const ClothModel>(sim.model()), desc.contact,
                                  std::move(obstacles));
  if (!term) return term;
  if (auto ok = (*term)->check_start(x); !ok) return fail(ok.error().message);
  return term;
}

}  // namespace

bool ClothWorldDesc::is_physical() const {
  return std::visit([](const auto& sheet) { return sheet.material.has_value(); }, cloth);
}

void use_fast_settings(ClothWorldDesc& world) {
  NewtonSettings newton;
  newton.linear_solver = LinearSolverKind::multigrid;
  newton.tolerance = 1e-4;
  newton.velocity_tolerance = 1e-3;
  // Measured on the built-in scenes: with Gauss-Newton's blocks CG's last digits cost more
  // than they save (drape-sphere 21 x 21, adaptive forcing: a worst step of 8.9 s against
  // 0.76 s with a fixed 10%).
  newton.linear_forcing = 0.1;
  // With contact, most iterations meet negative curvature and the exact attempt is thrown away
  // (drape-sphere 41 x 41, its first 15 frames: 705 of 926); projecting at once took 0.78 of
  // the time over its 60 frames. A free cotton sheet stays on the exact Hessian first: there
  // it saved 6% but ended 7 of 40 steps more than 0.1 mm from a tight solve, against 1.
  newton.projection = HessianProjection::with_terms;
  world.simulation.integrator = newton;
  world.choose_integrator = false;
  world.contact.hessian = BarrierHessian::adaptive;
}

void use_reference_contact_settings(ClothWorldDesc& world) {
  NewtonSettings newton;
  newton.linear_solver = LinearSolverKind::multigrid;
  newton.tolerance = 1e-4;
  world.simulation.integrator = newton;
  world.choose_integrator = false;
  world.contact.hessian = BarrierHessian::projected;
}

Result<ClothWorld> build_cloth_world(const ClothWorldDesc& desc) {
  if (auto error = desc.validate()) return fail(error->message);  // before the sheet's errors
  auto cloth = build_world_cloth(desc);
  if (!cloth) return fail(cloth.error().message);
  return build_cloth_world(desc, *cloth);
}

Result<ClothWorld> build_cloth_world(const ClothWorldDesc& desc, const ClothDesc& cloth) {
  if (auto error = desc.validate()) return fail(error->message);
  SimulationOptions options = desc.simulation;
  if (auto* newton = std::get_if<NewtonSettings>(&options.integrator);
      newton && desc.has_contact() && newton->max_iterations == NewtonSettings{}.max_iterations)
    newton->max_iterations = kContactNewtonIterations;
  auto sim = ClothSimulator::create(cloth, options);
  if (!sim) return fail(sim.error().message);

  std::vector<Collider> colliders;
  for (const ColliderDesc& c : desc.colliders) {
    auto collider = Collider::create(c, 0.0);
    if (!collider) return fail(collider.error().message);
    colliders.push_back(std::move(*collider));
  }
  std::shared_ptr<ContactTerm> contact;
  if (desc.has_contact()) {
    auto term = make_contact(desc, *sim, colliders);
    if (!term) return fail(term.error().message);
    contact = std::move(*term);
    if (auto ok = sim->add_energy_term(contact); !ok) return fail(ok.error().message);
  }
  std::shared_ptr<FrictionTerm> friction;
  if (desc.has_friction()) {
    // After contact: friction lags the contact term's pairs.
    auto term = FrictionTerm::create(contact, desc.friction_settings());
    if (!term) return fail(term.error().message);
    friction = std::move(*term);
    if (auto ok = sim->add_energy_term(friction); !ok) return fail(ok.error().message);
  }
  std::shared_ptr<AirTerm> air;
  if (desc.air) {
    auto term = AirTerm::create(sim->model(), *desc.air);
    if (!term) return fail(term.error().message);
    air = std::move(*term);
    if (auto ok = sim->add_energy_term(air); !ok) return fail(ok.error().message);
  }
  return ClothWorld{std::move(*sim), std::move(colliders), std::move(contact), std::move(friction),
                    std::move(air)};
}

}  // namespace animkit
