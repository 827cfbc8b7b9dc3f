#include "world_args.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <optional>
#include <vector>

#include "animkit/core/quote.h"
#include "cli_errors.h"

namespace animkit::cli {

void add_world_options(CLI::App& command, WorldArgs& args) {
  command.add_option("--sphere", args.spheres,
                     "A fixed sphere the cloth cannot pass through, CX,CY,CZ,R in m (repeatable)");
  command.add_option("--box", args.boxes,
                     "A fixed box, its centre and half sides CX,CY,CZ,HX,HY,HZ in m (repeatable)");
  command.add_option("--capsule", args.capsules,
                     "A fixed capsule, its centre, radius and half length CX,CY,CZ,R,H in m, "
                     "upright, or along the direction AX,AY,AZ given after them (repeatable)");
  command.add_option("--ground", args.ground, "A ground plane y = Y (m) the cloth rests on");
  command
      .add_option("--thickness", args.thickness,
                  "Contact distance in m: the cloth keeps this far from colliders and itself")
      ->capture_default_str();
  command.add_flag("--no-self-contact", args.no_self_contact,
                   "With a collider or --ground: let the cloth pass through itself");
  command
      .add_option("--friction", args.friction,
                  "With a collider or --ground: Coulomb friction coefficient of every contact "
                  "(cloth on colliders, ground and itself; 0: frictionless)")
      ->capture_default_str();
  command.add_option("--wind", args.wind,
                     "Wind velocity X,Y,Z in m/s: air drag and wind on the cloth's triangles");
  command.add_option("--gust", args.gust, "With --wind: the gusts' peak velocity X,Y,Z in m/s");
}

namespace {

// The comma-separated numbers of `text`, when there are `counts` of them (one of).
std::optional<std::vector<double>> numbers_of(const std::string& text,
                                              std::initializer_list<std::size_t> counts) {
  std::vector<double> values;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    std::size_t end = text.find(',', begin);
    if (end == std::string::npos) end = text.size();
    const std::string item = text.substr(begin, end - begin);
    char* stop = nullptr;
    const double value = std::strtod(item.c_str(), &stop);
    if (item.empty() || stop != item.c_str() + item.size()) return std::nullopt;
    values.push_back(value);
    begin = end + 1;
  }
  if (std::find(counts.begin(), counts.end(), values.size()) == counts.end()) return std::nullopt;
  return values;
}

// A fixed collider named "<kind> <index + 1>" at `centre`, turned by `rotation`.
Result<ColliderDesc> fixed_collider(const std::string& kind, int index, ColliderShape shape,
                                    const Vec3& centre, const Quat& rotation = Quat::Identity()) {
  ColliderDesc desc;
  desc.name = kind + " " + std::to_string(index + 1);
  desc.shape = std::move(shape);
  desc.motion = ScriptedMotion{.initial = {.position = centre, .rotation = rotation}};
  if (auto error = desc.validate()) return fail(error->message);
  return desc;
}

Result<ColliderDesc> sphere_of(const std::string& text, int index) {
  const auto v = numbers_of(text, {4});
  if (!v) return fail("--sphere expects CX,CY,CZ,R, got " + quote_input(text));
  return fixed_collider("sphere", index, SphereShape{(*v)[3]}, Vec3((*v)[0], (*v)[1], (*v)[2]));
}

Result<ColliderDesc> box_of(const std::string& text, int index) {
  const auto v = numbers_of(text, {6});
  if (!v) return fail("--box expects CX,CY,CZ,HX,HY,HZ, got " + quote_input(text));
  return fixed_collider("box", index, BoxShape{Vec3((*v)[3], (*v)[4], (*v)[5])},
                        Vec3((*v)[0], (*v)[1], (*v)[2]));
}

Result<ColliderDesc> capsule_of(const std::string& text, int index) {
  const auto v = numbers_of(text, {5, 8});
  if (!v)
    return fail("--capsule expects CX,CY,CZ,R,H or CX,CY,CZ,R,H,AX,AY,AZ, got " +
                quote_input(text));
  Quat rotation = Quat::Identity();  // the capsule's own axis is +y
  if (v->size() == 8) {
    const Vec3 axis((*v)[5], (*v)[6], (*v)[7]);
    if (!(axis.norm() > 0.0) || !std::isfinite(axis.norm()))
      return fail("--capsule's direction AX,AY,AZ must be a non-zero vector, got " +
                  quote_input(text));
    rotation = Quat::FromTwoVectors(Vec3::UnitY(), axis.normalized());
  }
  return fixed_collider("capsule", index, CapsuleShape{(*v)[3], (*v)[4]},
                        Vec3((*v)[0], (*v)[1], (*v)[2]), rotation);
}

}  // namespace

Result<void> apply_world_args(const WorldArgs& args, ClothWorldDesc& world) {
  const auto add = [&](const std::vector<std::string>& texts, auto parse) -> Result<void> {
    for (std::size_t i = 0; i < texts.size(); ++i) {
      auto collider = parse(texts[i], static_cast<int>(i));
      if (!collider) return fail(collider.error().message);
      collider->friction = args.friction;
      world.colliders.push_back(std::move(*collider));
    }
    return {};
  };
  if (auto ok = add(args.spheres, sphere_of); !ok) return ok;
  if (auto ok = add(args.boxes, box_of); !ok) return ok;
  if (auto ok = add(args.capsules, capsule_of); !ok) return ok;
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
