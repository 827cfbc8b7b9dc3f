#include "animkit/io/cloth_scene_writer.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "animkit/cloth/integrator_registry.h"
#include "animkit/cloth/material.h"

namespace animkit {

namespace {

using Json = nlohmann::ordered_json;

Json vec3(const Vec3& v) {
  return Json::array({v.x(), v.y(), v.z()});
}

// {"axis": [x, y, z], "degrees": d}, the form the reader takes (the identity about +y).
Json rotation(const Quat& q) {
  const Eigen::AngleAxisd turn(q.normalized());
  const bool none = turn.angle() == 0.0;
  return {{"axis", vec3(none ? Vec3(Vec3::UnitY()) : turn.axis())},
          {"degrees", turn.angle() * 180.0 / std::numbers::pi}};
}

Json material(const ClothMaterial& m, const std::string& preset_name) {
  const MaterialPreset* preset = find_material(preset_name);
  if (preset && preset->material.density == m.density && preset->material.stretch == m.stretch &&
      preset->material.shear == m.shear && preset->material.bending == m.bending &&
      preset->material.damping == m.damping) {
    return preset_name;
  }
  return {{"density", m.density},
          {"stretch", m.stretch},
          {"shear", m.shear},
          {"bending", m.bending},
          {"damping", m.damping}};
}

Json grid_cloth(const GridClothOptions& g, const std::string& material_name) {
  Json cloth;
  cloth["grid"] = g.cells;
  cloth["size"] = g.size;
  cloth["height"] = g.height;
  if (g.material) {
    cloth["material"] = material(*g.material, material_name);
  } else {
    cloth["mass"] = g.mass;
    cloth["stiffness"] = g.stiffness;
    cloth["damping"] = g.damping;
  }
  cloth["gravity"] = g.gravity;
  cloth["pins"] = g.pins == GridPins::corners ? "corners"
                  : g.pins == GridPins::edge  ? "edge"
                                              : "none";
  cloth["rotation"] = rotation(g.rotation);
  cloth["offset"] = vec3(g.offset);
  return cloth;
}

Result<Json> collider(const ColliderDesc& c) {
  Json out = {{"name", c.name}};
  if (const auto* s = std::get_if<SphereShape>(&c.shape)) {
    out["shape"] = "sphere";
    out["radius"] = s->radius;
  } else if (const auto* b = std::get_if<BoxShape>(&c.shape)) {
    out["shape"] = "box";
    out["half_extents"] = vec3(b->half_extents);
  } else if (const auto* k = std::get_if<CapsuleShape>(&c.shape)) {
    out["shape"] = "capsule";
    out["radius"] = k->radius;
    out["half_length"] = k->half_length;
  } else {
    return fail("collider '" + c.name +
                "' is a triangle mesh, which a scene file takes from an OBJ file: not written");
  }
  if (const auto* keyed = std::get_if<KeyframedMotion>(&c.motion)) {
    Json keys = Json::array();
    for (const Keyframe& key : keyed->keyframes) {
      keys.push_back({{"time", key.time},
                      {"position", vec3(key.position)},
                      {"rotation", rotation(key.rotation)}});
    }
    out["keyframes"] = keys;
  } else {
    const auto& scripted = std::get<ScriptedMotion>(c.motion);
    out["position"] = vec3(scripted.initial.position);
    out["rotation"] = rotation(scripted.initial.rotation);
    out["velocity"] = vec3(scripted.linear_velocity);
    out["angular_velocity"] = vec3(scripted.angular_velocity);
  }
  out["friction"] = c.friction;
  out["tessellation"] = c.tessellation;
  return out;
}

// Pretty JSON with every array of numbers on one line ([0.0, 0.25, 0.0], not five lines).
// Strings (names) are copied as they are, brackets in them included.
std::string with_short_arrays(const std::string& pretty) {
  std::string out;
  out.reserve(pretty.size());
  bool in_string = false;
  for (std::size_t i = 0; i < pretty.size(); ++i) {
    const char c = pretty[i];
    if (in_string) {
      out += c;
      if (c == '\\' && i + 1 < pretty.size()) {
        out += pretty[++i];
      } else if (c == '"') {
        in_string = false;
      }
      continue;
    }
    if (c == '"') in_string = true;
    const std::size_t end = c == '[' ? pretty.find(']', i) : std::string::npos;
    if (end == std::string::npos ||
        pretty.substr(i + 1, end - i - 1).find_first_of("[{\"") != std::string::npos) {
      out += c;
      continue;
    }
    // Numbers only: their lines joined.
    std::string items;
    bool space = false;
    for (char d : pretty.substr(i + 1, end - i - 1)) {
      if (d == ' ' || d == '\n') {
        space = true;
        continue;
      }
      if (space && !items.empty() && items.back() == ',') items += ' ';
      space = false;
      items += d;
    }
    out += "[" + items + "]";
    i = end;
  }
  return out;
}

}  // namespace

Result<std::string> cloth_scene_json(const ClothWorldDesc& scene) {
  const auto* grid = std::get_if<GridClothOptions>(&scene.cloth);
  if (!grid) {
    return fail(
        "the cloth is a triangle mesh, which a scene file takes from an OBJ file: not written");
  }
  Json out;
  out["cloth"] = grid_cloth(*grid, scene.material_name);
  out["colliders"] = Json::array();
  for (const ColliderDesc& c : scene.colliders) {
    auto written = collider(c);
    if (!written) return fail(written.error().message);
    out["colliders"].push_back(*written);
  }
  if (scene.ground) {
    out["ground"] = {{"height", scene.ground->height}, {"friction", scene.ground->friction}};
  }
  out["contact"] = {{"thickness", scene.contact.thickness},
                    {"stiffness", scene.contact.stiffness},
                    {"self_contact", scene.contact.self_contact},
                    {"hessian", std::string(barrier_hessian_name(scene.contact.hessian))},
                    {"self_friction", scene.self_friction},
                    {"friction_passes", scene.friction_passes}};
  if (scene.air) {
    const AirSettings& air = *scene.air;
    out["wind"] = {{"velocity", vec3(air.wind.velocity)},
                   {"gust", vec3(air.wind.gust)},
                   {"gust_frequency", air.wind.gust_frequency},
                   {"air_density", air.density},
                   {"normal_drag", air.normal_drag},
                   {"tangential_drag", air.tangential_drag}};
  }
  Json solver;
  solver["integrator"] = scene.choose_integrator
                             ? std::string("auto")
                             : std::string(integrator_entry(scene.simulation.integrator).name);
  if (auto tolerance = tolerance_of(scene.simulation.integrator)) solver["tolerance"] = *tolerance;
  if (!scene.choose_integrator) {
    if (const auto* newton = std::get_if<NewtonSettings>(&scene.simulation.integrator); newton) {
      if (newton->velocity_tolerance > 0.0)
        solver["velocity_tolerance"] = newton->velocity_tolerance;
      if (newton->linear_forcing > 0.0) solver["linear_forcing"] = newton->linear_forcing;
      solver["projection"] = std::string(enum_name(kHessianProjectionNames, newton->projection));
    }
  }
  solver["substeps"] = scene.simulation.substeps;
  out["solver"] = solver;
  out["dt"] = scene.time_step;
  out["frames"] = scene.frames;
  return with_short_arrays(out.dump(2)) + "\n";
}

}  // namespace animkit
