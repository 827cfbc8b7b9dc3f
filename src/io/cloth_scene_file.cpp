#include "animkit/io/cloth_scene_file.h"

#include <algorithm>
#include <limits>
#include <string>
#include <utility>

#include "animkit/cloth/integrator_registry.h"
#include "animkit/cloth/material.h"
#include "animkit/core/quote.h"
#include "animkit/io/file_bytes.h"
#include "animkit/io/obj_mesh.h"
#include "held_fp_exceptions.h"
#include "json_fields.h"

namespace animkit {

namespace {

// Reads the pieces of a scene; every error is a FieldError naming the key.
class SceneReader {
 public:
  explicit SceneReader(std::filesystem::path folder) : folder_(std::move(folder)) {}

  ClothWorldDesc read(const nlohmann::json& document) {
    JsonFields scene(document, "");
    ClothWorldDesc desc;
    if (const auto* cloth = scene.object("cloth")) read_cloth(*cloth, desc);
    if (const auto* colliders = scene.array("colliders")) {
      for (std::size_t i = 0; i < colliders->size(); ++i)
        desc.colliders.push_back(read_collider((*colliders)[i], element_path("colliders", i)));
    }
    if (const auto* ground = scene.object("ground")) {
      JsonFields fields(*ground, "ground");
      GroundDesc g;
      g.height = fields.number("height").value_or(g.height);
      g.friction = fields.number("friction").value_or(g.friction);
      fields.finish();
      desc.ground = g;
    }
    // Without a solver a scene with contact or a physical sheet solves as the built-in contact
    // scenes do (the lab's CG to 1e-6 is many times slower there: docs/contact.md); a
    // "contact" "hessian" still applies.
    const auto* solver = scene.object("solver");
    if (!solver && desc.fast_by_default()) use_fast_settings(desc);
    if (const auto* contact = scene.object("contact")) read_contact(*contact, desc);
    if (const auto* wind = scene.object("wind")) desc.air = read_air(*wind);
    if (solver) read_solver(*solver, desc);
    desc.time_step = scene.number("dt").value_or(desc.time_step);
    desc.frames = scene.integer("frames").value_or(desc.frames);
    scene.finish();
    return desc;
  }

 private:
  TriangleMesh read_mesh(JsonFields& fields, const char* key) {
    const std::string file = *fields.string(key);
    auto mesh = read_obj_mesh(folder_ / file);
    if (!mesh) fields.error(key, mesh.error().message);
    return std::move(*mesh);
  }

  static ClothMaterial read_material(JsonFields& fields, std::string& preset_name) {
    const char* key = "material";
    const nlohmann::json& value = *fields.object(key);
    if (value.is_string()) {
      const std::string name = *fields.string(key);
      const MaterialPreset* preset = find_material(name);
      if (!preset) fields.error(key, "unknown material preset " + quote_input(name));
      preset_name = name;
      return preset->material;
    }
    JsonFields m(value, fields.name(key));
    ClothMaterial material;
    material.density = m.number("density").value_or(material.density);
    material.stretch = m.number("stretch").value_or(material.stretch);
    material.shear = m.number("shear").value_or(material.shear);
    material.bending = m.number("bending").value_or(material.bending);
    material.damping = m.number("damping").value_or(material.damping);
    m.finish();
    return material;
  }

  void read_cloth(const nlohmann::json& object, ClothWorldDesc& desc) {
    JsonFields fields(object, "cloth");
    std::optional<ClothMaterial> material;
    if (fields.has("material")) material = read_material(fields, desc.material_name);
    const double gravity = fields.number("gravity").value_or(material ? 9.81 : 0.3);
    if (fields.has("mesh")) {
      MeshClothOptions mesh;
      mesh.mesh = read_mesh(fields, "mesh");
      mesh.source = "cloth.mesh " + (folder_ / *fields.string("mesh")).string();
      mesh.material = material;
      mesh.gravity = gravity;
      read_lab_parameters(fields, mesh.mass, mesh.stiffness, mesh.damping, material.has_value());
      mesh.warp = fields.vec3("warp").value_or(mesh.warp);
      if (const auto* pins = fields.array("pin")) {
        for (const auto& pin : *pins) {
          if (!pin.is_number_integer() || pin.get<long long>() < 0 ||
              pin.get<long long>() > std::numeric_limits<int>::max())
            fields.error("pin", "expected vertex indices (whole numbers from 0)");
          mesh.pins.push_back(static_cast<int>(pin.get<long long>()));
        }
      }
      if (const auto* boxes = fields.array("pin_box")) {
        for (const auto& box : *boxes) {
          if (!box.is_array() || box.size() != 6 ||
              !std::all_of(box.begin(), box.end(), [](const auto& e) { return e.is_number(); }))
            fields.error("pin_box", "expected boxes [x0, y0, z0, x1, y1, z1]");
          mesh.pin_boxes.emplace_back(Vec3(box[0], box[1], box[2]), Vec3(box[3], box[4], box[5]));
        }
      }
      desc.cloth = std::move(mesh);
    } else {
      GridClothOptions grid;
      grid.material = material;
      grid.gravity = gravity;
      read_lab_parameters(fields, grid.mass, grid.stiffness, grid.damping, material.has_value());
      grid.cells = fields.integer("grid").value_or(grid.cells);
      grid.size = fields.number("size").value_or(grid.size);
      grid.height = fields.number("height").value_or(grid.height);
      grid.rotation = fields.rotation("rotation").value_or(grid.rotation);
      grid.offset = fields.vec3("offset").value_or(grid.offset);
      if (auto pins = fields.string("pins")) {
        if (*pins == "corners")
          grid.pins = GridPins::corners;
        else if (*pins == "edge")
          grid.pins = GridPins::edge;
        else if (*pins == "none")
          grid.pins = GridPins::none;
        else
          fields.error("pins", "expected corners, edge or none, got " + quote_input(*pins));
      }
      desc.cloth = grid;
    }
    fields.finish();
  }

  static void read_lab_parameters(JsonFields& fields, double& mass, double& stiffness,
                                  double& damping, bool material) {
    for (const char* key : {"mass", "stiffness", "damping"}) {
      if (material && fields.has(key))
        fields.error(key, "the material sets masses, stiffnesses and damping");
    }
    mass = fields.number("mass").value_or(mass);
    stiffness = fields.number("stiffness").value_or(stiffness);
    damping = fields.number("damping").value_or(damping);
  }

  ColliderDesc read_collider(const nlohmann::json& object, const std::string& path) {
    JsonFields fields(object, path);
    ColliderDesc c;
    c.name = fields.string("name").value_or(path);
    const std::string shape = fields.string("shape").value_or("sphere");
    if (shape == "sphere") {
      c.shape = SphereShape{fields.number("radius").value_or(SphereShape{}.radius)};
    } else if (shape == "box") {
      c.shape = BoxShape{fields.vec3("half_extents").value_or(BoxShape{}.half_extents)};
    } else if (shape == "capsule") {
      c.shape = CapsuleShape{fields.number("radius").value_or(CapsuleShape{}.radius),
                             fields.number("half_length").value_or(CapsuleShape{}.half_length)};
    } else if (shape == "mesh") {
      if (!fields.has("mesh")) fields.error("mesh", "a mesh collider needs its OBJ file");
      c.shape = MeshShape{read_mesh(fields, "mesh")};
    } else {
      fields.error("shape", "expected sphere, box, capsule or mesh, got " + quote_input(shape));
    }
    if (const auto* keys = fields.array("keyframes")) {
      KeyframedMotion motion;
      for (std::size_t i = 0; i < keys->size(); ++i) {
        JsonFields k((*keys)[i], element_path(fields.name("keyframes"), i));
        Keyframe key;
        key.time = k.number("time").value_or(0.0);
        key.position = k.vec3("position").value_or(key.position);
        key.rotation = k.rotation("rotation").value_or(key.rotation);
        k.finish();
        motion.keyframes.push_back(key);
      }
      for (const char* scripted : {"position", "rotation", "velocity", "angular_velocity"}) {
        if (fields.has(scripted)) fields.error(scripted, "give either keyframes or a pose");
      }
      c.motion = std::move(motion);
    } else {
      ScriptedMotion motion;
      motion.initial.position = fields.vec3("position").value_or(Vec3::Zero());
      motion.initial.rotation = fields.rotation("rotation").value_or(Quat::Identity());
      motion.linear_velocity = fields.vec3("velocity").value_or(Vec3::Zero());
      motion.angular_velocity = fields.vec3("angular_velocity").value_or(Vec3::Zero());
      c.motion = motion;
    }
    c.friction = fields.number("friction").value_or(c.friction);
    c.tessellation = fields.integer("tessellation").value_or(c.tessellation);
    fields.finish();
    return c;
  }

  static void read_contact(const nlohmann::json& object, ClothWorldDesc& desc) {
    JsonFields fields(object, "contact");
    ContactSettings& contact = desc.contact;
    desc.self_friction = fields.number("self_friction").value_or(desc.self_friction);
    desc.friction_passes = fields.integer("friction_passes").value_or(desc.friction_passes);
    contact.thickness = fields.number("thickness").value_or(contact.thickness);
    contact.stiffness = fields.number("stiffness").value_or(contact.stiffness);
    contact.self_contact = fields.boolean("self_contact").value_or(contact.self_contact);
    if (auto name = fields.string("hessian")) {
      const std::optional<BarrierHessian> hessian = barrier_hessian_named(*name);
      if (!hessian) {
        fields.error("hessian", "expected one of " + joined_names(kBarrierHessianNames) +
                                    ", got " + quote_input(*name));
      }
      contact.hessian = *hessian;
    }
    fields.finish();
  }

  static AirSettings read_air(const nlohmann::json& object) {
    JsonFields fields(object, "wind");
    AirSettings air;
    air.wind.velocity = fields.vec3("velocity").value_or(air.wind.velocity);
    air.wind.gust = fields.vec3("gust").value_or(air.wind.gust);
    air.wind.gust_frequency = fields.number("gust_frequency").value_or(air.wind.gust_frequency);
    air.density = fields.number("air_density").value_or(air.density);
    air.normal_drag = fields.number("normal_drag").value_or(air.normal_drag);
    air.tangential_drag = fields.number("tangential_drag").value_or(air.tangential_drag);
    fields.finish();
    return air;
  }

  static void read_solver(const nlohmann::json& object, ClothWorldDesc& desc) {
    JsonFields fields(object, "solver");
    SimulationOptions& simulation = desc.simulation;
    if (auto name = fields.string("integrator"); name && *name == "auto") {
      desc.choose_integrator = true;  // the default's settings until a run has measured
    } else if (name) {
      const IntegratorEntry* entry = find_integrator(*name);
      if (!entry) {
        fields.error("integrator", "unknown integrator " + quote_input(*name) +
                                       " (expected auto or one of: " + integrator_names() + ")");
      }
      simulation.integrator = entry->defaults;
    }
    if (auto tolerance = fields.number("tolerance"))
      set_tolerance(simulation.integrator, *tolerance);
    // Newton's own settings: the named Newton integrator's, which `key` then changes (their
    // ranges are checked with the integrator's).
    const auto newton_for = [&](const char* key) -> NewtonSettings& {
      auto* newton = std::get_if<NewtonSettings>(&simulation.integrator);
      if (desc.choose_integrator)  // the winner's own settings replace the default's
        fields.error(key, "applies to a named Newton integrator, not 'auto'");
      if (!newton) {
        fields.error(key, "applies to the Newton integrators (implicit-*) only, not " +
                              quote_input(integrator_entry(simulation.integrator).name));
      }
      return *newton;
    };
    for (auto [key, setting] :
         {std::pair{"velocity_tolerance", &NewtonSettings::velocity_tolerance},
          std::pair{"linear_forcing", &NewtonSettings::linear_forcing}}) {
      if (const auto value = fields.number(key)) newton_for(key).*setting = *value;
    }
    if (auto name = fields.string("projection")) {
      NewtonSettings& newton = newton_for("projection");
      const auto projection = enum_named<HessianProjection>(kHessianProjectionNames, *name);
      if (!projection) {
        fields.error("projection", "expected one of " + joined_names(kHessianProjectionNames) +
                                       ", got " + quote_input(*name));
      }
      newton.projection = *projection;
    }
    simulation.substeps = fields.integer("substeps").value_or(simulation.substeps);
    fields.finish();
  }

  std::filesystem::path folder_;
};

}  // namespace

Result<ClothWorldDesc> parse_cloth_scene(std::string_view text, std::string_view name,
                                         const std::filesystem::path& folder) {
  const std::string prefix = std::string(name) + ": ";
  const HeldFloatingPointExceptions held;  // huge numbers parse to infinity, refused below
  auto parsed = parse_json_document(text, prefix);
  if (!parsed) return fail(parsed.error().message);
  const nlohmann::json& document = *parsed;
  ClothWorldDesc desc;
  try {
    desc = SceneReader(folder).read(document);
  } catch (const FieldError& e) {
    return fail(prefix + e.what());
  }
  if (auto error = desc.validate()) return fail(prefix + error->message);
  return desc;
}

Result<ClothWorldDesc> read_cloth_scene(const std::filesystem::path& path) {
  auto bytes = read_file_bytes(path, kMaxSceneFileBytes);
  if (!bytes) return fail(bytes.error().message);
  return parse_cloth_scene(*bytes, shown_path(path.string()), path.parent_path());
}

}  // namespace animkit
