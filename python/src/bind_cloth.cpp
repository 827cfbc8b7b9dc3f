// Bindings of whole cloth scenes (ClothWorldDesc: a sheet, what it meets, the solver, the run)
// and the module's cloth part: bind_cloth() registers every cloth binding file in order. The
// simulator is in bind_cloth_simulator.cpp.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <variant>

#include "animkit/cloth/cloth_world.h"
#include "animkit/cloth/integrator_registry.h"
#include "animkit/cloth/material.h"
#include "animkit/cloth/mesh_cloth.h"
#include "animkit/io/cloth_scene_file.h"
#include "animkit/scene/cloth_scenes.h"
#include "bindings.h"
#include "cloth_convert.h"
#include "cloth_simulator_object.h"
#include "numpy_convert.h"
#include "python_errors.h"

namespace animkit::python {
namespace {

py::object cloth_object(const ClothWorldDesc& d) {
  if (const auto* g = std::get_if<GridClothOptions>(&d.cloth)) return py::cast(*g);
  return py::cast(std::get<MeshClothOptions>(d.cloth));
}

void set_cloth(ClothWorldDesc& d, const py::handle& cloth) {
  if (cloth.is_none()) {
    d.cloth = GridClothOptions{};
  } else if (py::isinstance<GridClothOptions>(cloth)) {
    d.cloth = cloth.cast<GridClothOptions>();
  } else if (py::isinstance<MeshClothOptions>(cloth)) {
    d.cloth = cloth.cast<MeshClothOptions>();
  } else {
    throw py::type_error("cloth must be a GridCloth or a MeshCloth");
  }
}

// Settings, a registry name, or "auto" (the simulator measures and chooses).
void set_integrator(ClothWorldDesc& d, const py::handle& value) {
  if (py::isinstance<py::str>(value) && value.cast<std::string>() == "auto") {
    d.choose_integrator = true;
    return;
  }
  d.simulation.integrator = to_integrator(value);
  d.choose_integrator = false;
}

std::string repr_scene(const ClothWorldDesc& d) {
  std::string colliders = "[";
  for (const ColliderDesc& c : d.colliders)
    colliders += (colliders.size() > 1 ? ", " : "") + repr_collider(c);
  colliders += "]";
  const std::string cloth = std::holds_alternative<GridClothOptions>(d.cloth)
                                ? repr_grid(std::get<GridClothOptions>(d.cloth))
                                : repr_mesh(std::get<MeshClothOptions>(d.cloth));
  return "ClothScene(cloth=" + cloth + ", colliders=" + colliders + ", ground=" +
         (d.ground ? "Ground(height=" + repr_number(d.ground->height) +
                         ", friction=" + repr_number(d.ground->friction) + ")"
                   : std::string("None")) +
         ", contact=" + py::repr(py::cast(d.contact)).cast<std::string>() +
         ", self_friction=" + repr_number(d.self_friction) +
         ", friction_passes=" + std::to_string(d.friction_passes) +
         ", air=" + (d.air ? py::repr(py::cast(*d.air)).cast<std::string>() : "None") +
         ", integrator=" +
         (d.choose_integrator ? std::string("'auto'") : repr_integrator(d.simulation.integrator)) +
         ", substeps=" + std::to_string(d.simulation.substeps) +
         ", dt=" + repr_number(d.time_step) + ", frames=" + std::to_string(d.frames) +
         ", material_name=" + quoted(d.material_name) + ")";
}

std::string scene_names() {
  return cloth_scene_names();
}

void bind_scenes(py::module_& m) {
  const ClothWorldDesc world;
  py::class_<ClothWorldDesc>(
      m, "ClothScene",
      "A whole cloth run as data (the library's ClothWorldDesc, what a JSON scene file holds): "
      "the sheet, the colliders, the ground, contact and air, the integrator and the run's "
      "length. Every attribute holding a sub-object (cloth, colliders, ground, contact, air, "
      "integrator) returns a copy: change it, then assign it back (scene.contact.thickness = "
      "0.01 changes only a copy; c = scene.contact; c.thickness = 0.01; scene.contact = c "
      "changes the scene).")
      .def(py::init([](py::object cloth, std::vector<ColliderDesc> colliders,
                       std::optional<GroundDesc> ground, std::optional<ContactSettings> contact,
                       std::optional<AirSettings> air, py::object integrator, int substeps,
                       double dt, int frames, double self_friction, int friction_passes,
                       std::string material_name) {
             ClothWorldDesc d;
             set_cloth(d, cloth);
             d.colliders = std::move(colliders);
             d.ground = ground;
             // With contact or a material and no integrator given, the fast settings (Newton's,
             // and the barrier Hessian unless `contact` gives one).
             if (integrator.is_none() && d.fast_by_default()) use_fast_settings(d);
             if (contact) d.contact = *contact;
             d.air = air;
             if (!integrator.is_none()) set_integrator(d, integrator);
             d.simulation.substeps = substeps;
             d.time_step = dt;
             d.frames = frames;
             d.self_friction = self_friction;
             d.friction_passes = friction_passes;
             d.material_name = std::move(material_name);
             check(d.validate());
             return d;
           }),
           "cloth: a GridCloth (default: the lab's) or a MeshCloth; colliders: a list of "
           "Collider (distinct names); ground: a Ground or None; contact: ContactSettings (None: "
           "the defaults); air: AirSettings or None (still air); integrator: NewtonSettings "
           "(default; with colliders, ground or a material, the fast settings of "
           "docs/contact.md), VbdSettings, LocalGlobalSettings, ExplicitEulerSettings or a "
           "registry name (integrator_names()); substeps per step (0: the integrator's "
           "default); dt: s per frame; frames: the run's length; self_friction: mu between "
           "parts of the cloth; friction_passes: friction's lagging passes; material_name: for "
           "reports. Raises animkit.Error naming the first invalid part.",
           py::arg("cloth") = py::none(), py::arg("colliders") = std::vector<ColliderDesc>{},
           py::arg("ground") = py::none(), py::arg("contact") = py::none(),
           py::arg("air") = py::none(), py::arg("integrator") = py::none(),
           py::arg("substeps") = world.simulation.substeps, py::arg("dt") = world.time_step,
           py::arg("frames") = world.frames, py::arg("self_friction") = world.self_friction,
           py::arg("friction_passes") = world.friction_passes,
           py::arg("material_name") = world.material_name)
      .def_static(
          "builtin",
          [](const std::string& name) {
            const ClothSceneEntry* entry = find_cloth_scene(name);
            if (!entry)
              raise("unknown scene '" + name + "' (expected one of: " + scene_names() + ")");
            return entry->make();
          },
          "The built-in scene called `name` (see builtin_cloth_scene_names(); 'lab' is the "
          "lab's hanging cloth), as `animkit cloth --scene NAME` runs it. Raises animkit.Error "
          "for an unknown name.",
          py::arg("name"))
      .def_property("cloth", &cloth_object, &set_cloth,
                    "The sheet: a GridCloth or a MeshCloth (a copy; assign it back to change "
                    "the scene).")
      .def_property(
          "colliders", [](const ClothWorldDesc& d) { return d.colliders; },
          [](ClothWorldDesc& d, std::vector<ColliderDesc> v) { d.colliders = std::move(v); },
          "The colliders, a list of Collider (copies; assign a list back to change the scene).")
      .def_property(
          "ground", [](const ClothWorldDesc& d) { return d.ground; },
          [](ClothWorldDesc& d, std::optional<GroundDesc> v) { d.ground = std::move(v); },
          "The Ground, or None (a copy; assign it back to change the scene).")
      .def_property(
          "contact", [](const ClothWorldDesc& d) { return d.contact; },
          [](ClothWorldDesc& d, const ContactSettings& v) { d.contact = v; },
          "The ContactSettings (a copy; assign it back to change the scene).")
      .def_property(
          "air", [](const ClothWorldDesc& d) { return d.air; },
          [](ClothWorldDesc& d, std::optional<AirSettings> v) { d.air = std::move(v); },
          "AirSettings, or None for still air (a copy; assign it back to change the scene).")
      .def_readwrite("self_friction", &ClothWorldDesc::self_friction,
                     "Coulomb coefficient between parts of the cloth.")
      .def_readwrite("friction_passes", &ClothWorldDesc::friction_passes,
                     "Friction's lagging passes per substep, >= 1.")
      .def_readwrite("material_name", &ClothWorldDesc::material_name,
                     "The material preset's name, for reports ('' if none).")
      .def_property(
          "integrator",
          [](const ClothWorldDesc& d) { return integrator_object(d.simulation.integrator); },
          [](ClothWorldDesc& d, py::object v) { set_integrator(d, v); },
          "The integrator's settings (a copy; assign it back to change the scene); accepts a "
          "registry name too, or 'auto': ClothSimulator then measures the integrators on the "
          "scene's first steps and keeps the fastest.")
      .def_property_readonly(
          "integrator_name",
          [](const ClothWorldDesc& d) {
            return d.choose_integrator
                       ? std::string("auto")
                       : std::string(integrator_entry(d.simulation.integrator).name);
          },
          "The integrator's registry name, e.g. 'implicit-pcg', or 'auto' (see integrator).")
      .def_property(
          "substeps", [](const ClothWorldDesc& d) { return d.simulation.substeps; },
          [](ClothWorldDesc& d, int v) { d.simulation.substeps = v; },
          "Substeps per step (0: the integrator's default).")
      .def_readwrite("dt", &ClothWorldDesc::time_step, "Seconds per frame (step).")
      .def_readwrite("frames", &ClothWorldDesc::frames, "Frames (steps) a run() takes.")
      .def(
          "validate", [](const ClothWorldDesc& d) { check(d.validate()); },
          "Raises animkit.Error naming the first invalid part; returns None when valid.")
      .def("__repr__", &repr_scene);

  m.def(
      "builtin_cloth_scene_names",
      [] {
        std::vector<std::string> names;
        for (const ClothSceneEntry& e : cloth_scenes()) names.emplace_back(e.name);
        return names;
      },
      "The built-in scenes' names, 'lab' first.");
  m.def(
      "read_cloth_scene",
      [](const std::filesystem::path& path) { return unwrap(read_cloth_scene(path)); },
      "A JSON scene file (the format `animkit cloth --scene FILE.json` reads; OBJ paths "
      "relative to its folder). Raises animkit.Error for a missing, unreadable or invalid file, "
      "naming the key.",
      py::arg("path"));
  m.def(
      "parse_cloth_scene",
      [](const std::string& text, const std::filesystem::path& folder, const std::string& name) {
        return unwrap(parse_cloth_scene(text, name, folder));
      },
      "A scene from JSON text; OBJ files it names are read from `folder`; `name` starts the "
      "error messages. Raises animkit.Error for bad JSON or an invalid scene.",
      py::arg("text"), py::arg("folder") = std::filesystem::path("."),
      py::arg("name") = std::string("scene"));
}

}  // namespace

void bind_cloth(py::module_& m) {
  bind_sheets(m);
  bind_colliders(m);
  bind_integrators(m);
  bind_scenes(m);
  bind_cloth_sinks(m);
  bind_cloth_simulator(m);
}

}  // namespace animkit::python
