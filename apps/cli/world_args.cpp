#include "world_args.h"

#include <memory>

#include "animkit/cloth/aerodynamics.h"
#include "animkit/cloth/contact.h"
#include "animkit/collision/collider_surface.h"
#include "animkit/core/quote.h"
#include "cli_errors.h"

namespace animkit::cli {

void add_world_options(CLI::App& command, WorldArgs& args) {
  command.add_option("--sphere", args.spheres,
                     "A fixed sphere the cloth cannot pass through, CX,CY,CZ,R in m (repeatable)");
  command.add_option("--ground", args.ground, "A ground plane y = Y (m) the cloth rests on");
  command
      .add_option("--thickness", args.thickness,
                  "Contact distance in m: the cloth keeps this far from colliders and itself")
      ->capture_default_str();
  command.add_flag("--no-self-contact", args.no_self_contact,
                   "With --sphere or --ground: let the cloth pass through itself");
  command.add_option("--wind", args.wind,
                     "Wind velocity X,Y,Z in m/s: air drag and wind on the cloth's triangles");
  command.add_option("--gust", args.gust, "With --wind: the gusts' peak velocity X,Y,Z in m/s");
}

namespace {

Result<Collider> sphere_of(const std::string& text, int index) {
  const std::size_t comma = text.rfind(',');
  Vec3 center;
  char* end = nullptr;
  const std::string radius_text = comma == std::string::npos ? "" : text.substr(comma + 1);
  const double radius = std::strtod(radius_text.c_str(), &end);
  if (comma == std::string::npos || !parse_vec3(text.substr(0, comma), center) ||
      radius_text.empty() || end != radius_text.c_str() + radius_text.size()) {
    return fail("--sphere expects CX,CY,CZ,R, got " + quote_input(text));
  }
  ColliderDesc desc;
  desc.name = "sphere " + std::to_string(index + 1);
  desc.shape = SphereShape{radius};
  desc.motion = ScriptedMotion{.initial = {.position = center}};
  return Collider::create(desc);
}

}  // namespace

Result<std::vector<Collider>> add_world(ClothSimulator& sim, const WorldArgs& args) {
  std::vector<Collider> colliders;
  for (std::size_t i = 0; i < args.spheres.size(); ++i) {
    auto sphere = sphere_of(args.spheres[i], static_cast<int>(i));
    if (!sphere) return fail(sphere.error().message);
    colliders.push_back(std::move(*sphere));
  }
  const auto model = std::make_shared<const ClothModel>(sim.model());
  if (args.any_contact()) {
    if (auto inside = find_particle_inside(sim.state().positions, colliders))
      return fail(inside->message);
    ContactObstacles obstacles{.meshes = {}, .ground_height = args.ground};
    for (const Collider& c : colliders)
      obstacles.meshes.push_back({c.world_vertices(), c.model().surface.triangles});
    if (args.ground) {
      for (int i = 0; i < model->particle_count(); ++i) {
        if (sim.state().position(i).y() <= *args.ground)
          return fail("particle " + std::to_string(i) + " starts on or below the ground");
      }
    }
    auto contact = ContactTerm::create(
        model, {.thickness = args.thickness, .self_contact = !args.no_self_contact},
        std::move(obstacles));
    if (!contact) return fail(contact.error().message);
    if (auto ok = sim.add_energy_term(*contact); !ok) return fail(ok.error().message);
  }
  if (!args.wind.empty() || !args.gust.empty()) {
    AirSettings air;
    if (!args.wind.empty() && !parse_vec3(args.wind, air.wind.velocity))
      return fail("--wind expects X,Y,Z in m/s, got " + quote_input(args.wind));
    if (!args.gust.empty() && !parse_vec3(args.gust, air.wind.gust))
      return fail("--gust expects X,Y,Z in m/s, got " + quote_input(args.gust));
    auto term = AirTerm::create(*model, air);
    if (!term) return fail(term.error().message);
    if (auto ok = sim.add_energy_term(*term); !ok) return fail(ok.error().message);
  }
  return colliders;
}

}  // namespace animkit::cli
