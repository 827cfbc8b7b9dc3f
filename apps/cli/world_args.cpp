#include "world_args.h"

#include <memory>

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
  command
      .add_option("--friction", args.friction,
                  "With --sphere or --ground: Coulomb friction coefficient of every contact "
                  "(cloth on spheres, ground and itself; 0: frictionless)")
      ->capture_default_str();
  command.add_option("--wind", args.wind,
                     "Wind velocity X,Y,Z in m/s: air drag and wind on the cloth's triangles");
  command.add_option("--gust", args.gust, "With --wind: the gusts' peak velocity X,Y,Z in m/s");
}

namespace {

Result<ColliderDesc> sphere_of(const std::string& text, int index) {
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
  if (auto error = desc.validate()) return fail(error->message);
  return desc;
}

}  // namespace

Result<void> apply_world_args(const WorldArgs& args, ClothWorldDesc& world) {
  for (std::size_t i = 0; i < args.spheres.size(); ++i) {
    auto sphere = sphere_of(args.spheres[i], static_cast<int>(i));
    if (!sphere) return fail(sphere.error().message);
    sphere->friction = args.friction;
    world.colliders.push_back(std::move(*sphere));
  }
  if (args.ground) world.ground = GroundDesc{.height = *args.ground, .friction = args.friction};
  world.self_friction = args.friction;
  world.contact.thickness = args.thickness;
  world.contact.self_contact = !args.no_self_contact;
  if (!args.wind.empty() || !args.gust.empty()) {
    AirSettings air;
    if (!args.wind.empty() && !parse_vec3(args.wind, air.wind.velocity))
      return fail("--wind expects X,Y,Z in m/s, got " + quote_input(args.wind));
    if (!args.gust.empty() && !parse_vec3(args.gust, air.wind.gust))
      return fail("--gust expects X,Y,Z in m/s, got " + quote_input(args.gust));
    world.air = air;
  }
  return {};
}

}  // namespace animkit::cli
