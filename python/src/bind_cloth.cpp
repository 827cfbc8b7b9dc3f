// Bindings of animkit's cloth descriptions: materials, the grid and mesh sheets, colliders,
// ground, contact, air, the integrators' settings and whole scenes (ClothWorldDesc). The
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

// ---- shared conversions (cloth_convert.h) ----

std::string repr_number(double value) {
  return py::repr(py::float_(value)).cast<std::string>();
}

std::string repr_vec3(const Vec3& v) {
  return "(" + repr_number(v.x()) + ", " + repr_number(v.y()) + ", " + repr_number(v.z()) + ")";
}

std::string repr_quat(const Quat& q) {
  return "(" + repr_number(q.w()) + ", " + repr_number(q.x()) + ", " + repr_number(q.y()) + ", " +
         repr_number(q.z()) + ")";
}

std::vector<std::array<int, 3>> to_triangles(const py::handle& value, std::string_view what) {
  DoubleArray array = as_double_array(value, what);
  if (array.ndim() == 1 && array.shape(0) == 0) return {};
  if (array.ndim() != 2 || array.shape(1) != 3) {
    std::string shape = "(";
    for (py::ssize_t d = 0; d < array.ndim(); ++d)
      shape += (d > 0 ? ", " : "") + std::to_string(array.shape(d));
    raise(std::string(what) + " must be an array of shape (m, 3) of vertex indices, got shape " +
          shape + (array.ndim() == 1 ? ",)" : ")"));
  }
  std::vector<std::array<int, 3>> triangles(static_cast<std::size_t>(array.shape(0)));
  const auto view = array.unchecked<2>();
  for (py::ssize_t t = 0; t < array.shape(0); ++t) {
    for (py::ssize_t c = 0; c < 3; ++c) {
      const double index = view(t, c);
      if (!(std::floor(index) == index && std::abs(index) <= std::numeric_limits<int>::max())) {
        raise(std::string(what) + " must hold integer vertex indices, got " + repr_number(index) +
              " in row " + std::to_string(t));
      }
      triangles[static_cast<std::size_t>(t)][static_cast<std::size_t>(c)] = static_cast<int>(index);
    }
  }
  return triangles;
}

py::array_t<int> triangles_to_array(std::span<const std::array<int, 3>> triangles) {
  py::array_t<int> out({static_cast<py::ssize_t>(triangles.size()), py::ssize_t{3}});
  auto view = out.mutable_unchecked<2>();
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int c = 0; c < 3; ++c)
      view(static_cast<py::ssize_t>(t), c) = triangles[t][static_cast<std::size_t>(c)];
  return out;
}

namespace {

// ---- enums as the strings the scene files use ----

template <class E>
struct Named {
  const char* name;
  E value;
};

constexpr Named<GridPins> kPins[] = {
    {"corners", GridPins::corners}, {"edge", GridPins::edge}, {"none", GridPins::none}};
constexpr Named<LinearSolverKind> kSolvers[] = {{"direct", LinearSolverKind::direct},
                                                {"pcg", LinearSolverKind::pcg},
                                                {"multigrid", LinearSolverKind::multigrid}};
constexpr Named<HessianProjection> kProjections[] = {
    {"when_indefinite", HessianProjection::when_indefinite}, {"always", HessianProjection::always}};

template <class E, std::size_t N>
E parse_enum(const std::string& text, const Named<E> (&names)[N], std::string_view what) {
  std::string expected;
  for (const auto& named : names) {
    if (text == named.name) return named.value;
    expected += (expected.empty() ? "" : ", ") + std::string(named.name);
  }
  raise("unknown " + std::string(what) + " '" + text + "' (expected one of: " + expected + ")");
}

template <class E, std::size_t N>
std::string enum_name(E value, const Named<E> (&names)[N]) {
  for (const auto& named : names)
    if (named.value == value) return named.name;
  return "?";
}

std::string quoted(const std::string& text) {
  return py::repr(py::str(text)).cast<std::string>();
}

std::string material_names() {
  std::string names;
  for (const MaterialPreset& preset : material_presets())
    names += (names.empty() ? "" : ", ") + std::string(preset.name);
  return names;
}

std::string repr_material(const ClothMaterial& m) {
  return "Material(density=" + repr_number(m.density) + ", stretch=" + repr_number(m.stretch) +
         ", shear=" + repr_number(m.shear) + ", bending=" + repr_number(m.bending) +
         ", damping=" + repr_number(m.damping) + ")";
}

// Gravity when the caller gives none: SI with a physical material, the lab's without (as the
// scene files have it, io/cloth_scene_file.h).
double default_gravity(const std::optional<ClothMaterial>& material) {
  return material ? 9.81 : GridClothOptions{}.gravity;
}

// ---- colliders ----

std::vector<Keyframe> to_keyframes(const py::handle& value) {
  std::vector<Keyframe> keyframes;
  if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value))
    raise("keyframes must be a list of (time, position) or (time, position, rotation)");
  std::size_t index = 0;
  for (const py::handle item : value) {
    const std::string what = "keyframes[" + std::to_string(index++) + "]";
    if (!py::isinstance<py::sequence>(item) || py::isinstance<py::str>(item) ||
        (py::len(item) != 2 && py::len(item) != 3)) {
      raise(what + " must be (time, position) or (time, position, rotation)");
    }
    const py::sequence entry = py::reinterpret_borrow<py::sequence>(item);
    Keyframe keyframe;
    try {
      keyframe.time = entry[0].cast<double>();
    } catch (const py::cast_error&) {
      raise(what + ": time must be a number");
    }
    keyframe.position = to_vec3(entry[1], what + ".position");
    if (py::len(entry) == 3) keyframe.rotation = to_quat(entry[2], what + ".rotation");
    keyframes.push_back(keyframe);
  }
  return keyframes;
}

ColliderDesc make_collider(std::string name, ColliderShape shape, const py::handle& position,
                           const py::handle& rotation, const py::handle& velocity,
                           const py::handle& angular_velocity, const py::handle& keyframes,
                           double friction, int tessellation) {
  ColliderDesc desc;
  desc.name = std::move(name);
  desc.shape = std::move(shape);
  desc.friction = friction;
  desc.tessellation = tessellation;
  ScriptedMotion scripted;
  scripted.initial.position = to_vec3(position, "position");
  scripted.initial.rotation = to_quat(rotation, "rotation");
  scripted.linear_velocity = to_vec3(velocity, "velocity");
  scripted.angular_velocity = to_vec3(angular_velocity, "angular_velocity");
  if (!keyframes.is_none()) {
    if (!scripted.linear_velocity.isZero(0.0) || !scripted.angular_velocity.isZero(0.0))
      raise("collider '" + desc.name + "': give velocities or keyframes, not both");
    desc.motion = KeyframedMotion{to_keyframes(keyframes)};
  } else {
    desc.motion = scripted;
  }
  check(desc.validate());
  return desc;
}

std::string shape_name(const ColliderShape& shape) {
  return std::visit(
      [](const auto& s) -> std::string {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, PlaneShape>) return "plane";
        if constexpr (std::is_same_v<S, SphereShape>) return "sphere";
        if constexpr (std::is_same_v<S, BoxShape>) return "box";
        if constexpr (std::is_same_v<S, CapsuleShape>) return "capsule";
        return "mesh";
      },
      shape);
}

std::string repr_collider(const ColliderDesc& c) {
  std::string text = "Collider." + shape_name(c.shape) + "(" + quoted(c.name);
  if (const auto* s = std::get_if<SphereShape>(&c.shape))
    text += ", radius=" + repr_number(s->radius);
  if (const auto* b = std::get_if<BoxShape>(&c.shape))
    text += ", half_extents=" + repr_vec3(b->half_extents);
  if (const auto* s = std::get_if<CapsuleShape>(&c.shape)) {
    text += ", radius=" + repr_number(s->radius) + ", half_length=" + repr_number(s->half_length);
  }
  if (const auto* p = std::get_if<PlaneShape>(&c.shape))
    text += ", display_size=" + repr_number(p->display_size);
  if (const auto* m = std::get_if<MeshShape>(&c.shape)) {
    text += ", vertices=<" + std::to_string(m->mesh.vertices.size()) + ">, triangles=<" +
            std::to_string(m->mesh.triangles.size()) + ">";
  }
  if (const auto* s = std::get_if<ScriptedMotion>(&c.motion)) {
    text += ", position=" + repr_vec3(s->initial.position) +
            ", rotation=" + repr_quat(s->initial.rotation) +
            ", velocity=" + repr_vec3(s->linear_velocity) +
            ", angular_velocity=" + repr_vec3(s->angular_velocity);
  } else {
    text += ", keyframes=<" + std::to_string(std::get<KeyframedMotion>(c.motion).keyframes.size()) +
            ">";
  }
  return text + ", friction=" + repr_number(c.friction) +
         ", tessellation=" + std::to_string(c.tessellation) + ")";
}

const ScriptedMotion* scripted(const ColliderDesc& c) {
  return std::get_if<ScriptedMotion>(&c.motion);
}

void bind_colliders(py::module_& m) {
  py::class_<ColliderDesc> collider(
      m, "Collider",
      "A solid the cloth collides with: a sphere, box, capsule, plane or triangle mesh, at rest, "
      "moving at constant velocities (scripted) or along keyframes. Make one with "
      "Collider.sphere(), .box(), .capsule(), .plane() or .mesh(). Lengths in m, times in s, "
      "angles in rad; rotations are unit quaternions (w, x, y, z).");
  const ColliderDesc defaults;
  const ScriptedMotion motion;
  const py::tuple origin = py::make_tuple(0.0, 0.0, 0.0);
  const py::tuple identity = py::make_tuple(1.0, 0.0, 0.0, 0.0);
  const char* motion_doc =
      " position, rotation: the pose at t = 0 (world = rotation * local + position); velocity "
      "(m/s) and angular_velocity (rad/s, world axes, about the collider's origin) move it at "
      "constant rates; or keyframes, a list of (time, position) or (time, position, rotation), "
      "interpolated linearly (slerp for rotations). friction: Coulomb coefficient mu, >= 0. "
      "tessellation: the surface's subdivision level. Raises animkit.Error on any invalid "
      "value (the library's message, naming the collider).";
  collider.def_static(
      "sphere",
      [](std::string name, double radius, py::object position, py::object rotation,
         py::object velocity, py::object angular_velocity, py::object keyframes, double friction,
         int tessellation) {
        return make_collider(std::move(name), SphereShape{radius}, position, rotation, velocity,
                             angular_velocity, keyframes, friction, tessellation);
      },
      (std::string("A ball of `radius` m centred on its origin.") + motion_doc).c_str(),
      py::arg("name"), py::arg("radius") = SphereShape{}.radius, py::arg("position") = origin,
      py::arg("rotation") = identity, py::arg("velocity") = origin,
      py::arg("angular_velocity") = origin, py::arg("keyframes") = py::none(),
      py::arg("friction") = defaults.friction, py::arg("tessellation") = defaults.tessellation);
  collider.def_static(
      "box",
      [](std::string name, py::object half_extents, py::object position, py::object rotation,
         py::object velocity, py::object angular_velocity, py::object keyframes, double friction,
         int tessellation) {
        return make_collider(std::move(name), BoxShape{to_vec3(half_extents, "half_extents")},
                             position, rotation, velocity, angular_velocity, keyframes, friction,
                             tessellation);
      },
      (std::string("A box with `half_extents` (m, along its local x, y, z) centred on its "
                   "origin.") +
       motion_doc)
          .c_str(),
      py::arg("name"), py::arg("half_extents") = py::make_tuple(0.5, 0.5, 0.5),
      py::arg("position") = origin, py::arg("rotation") = identity, py::arg("velocity") = origin,
      py::arg("angular_velocity") = origin, py::arg("keyframes") = py::none(),
      py::arg("friction") = defaults.friction, py::arg("tessellation") = defaults.tessellation);
  collider.def_static(
      "capsule",
      [](std::string name, double radius, double half_length, py::object position,
         py::object rotation, py::object velocity, py::object angular_velocity,
         py::object keyframes, double friction, int tessellation) {
        return make_collider(std::move(name), CapsuleShape{radius, half_length}, position, rotation,
                             velocity, angular_velocity, keyframes, friction, tessellation);
      },
      (std::string("A capsule: the points within `radius` m of the segment along local y from "
                   "-half_length to +half_length.") +
       motion_doc)
          .c_str(),
      py::arg("name"), py::arg("radius") = CapsuleShape{}.radius,
      py::arg("half_length") = CapsuleShape{}.half_length, py::arg("position") = origin,
      py::arg("rotation") = identity, py::arg("velocity") = origin,
      py::arg("angular_velocity") = origin, py::arg("keyframes") = py::none(),
      py::arg("friction") = defaults.friction, py::arg("tessellation") = defaults.tessellation);
  collider.def_static(
      "plane",
      [](std::string name, double display_size, py::object position, py::object rotation,
         py::object velocity, py::object angular_velocity, py::object keyframes, double friction,
         int tessellation) {
        return make_collider(std::move(name), PlaneShape{display_size}, position, rotation,
                             velocity, angular_velocity, keyframes, friction, tessellation);
      },
      (std::string("The plane y = 0 of its local frame, solid below (normal +y); drawn as a "
                   "square of `display_size` m.") +
       motion_doc)
          .c_str(),
      py::arg("name"), py::arg("display_size") = PlaneShape{}.display_size,
      py::arg("position") = origin, py::arg("rotation") = identity, py::arg("velocity") = origin,
      py::arg("angular_velocity") = origin, py::arg("keyframes") = py::none(),
      py::arg("friction") = defaults.friction, py::arg("tessellation") = defaults.tessellation);
  collider.def_static(
      "mesh",
      [](std::string name, py::object vertices, py::object triangles, py::object position,
         py::object rotation, py::object velocity, py::object angular_velocity,
         py::object keyframes, double friction, int tessellation) {
        MeshShape shape;
        shape.mesh.vertices = to_vec3s(vertices, "vertices");
        shape.mesh.triangles = to_triangles(triangles, "triangles");
        return make_collider(std::move(name), std::move(shape), position, rotation, velocity,
                             angular_velocity, keyframes, friction, tessellation);
      },
      (std::string("A triangle mesh: vertices (n, 3) in m in its local frame, triangles (m, 3) "
                   "vertex indices, closed and counter-clockwise seen from outside.") +
       motion_doc)
          .c_str(),
      py::arg("name"), py::arg("vertices"), py::arg("triangles"), py::arg("position") = origin,
      py::arg("rotation") = identity, py::arg("velocity") = origin,
      py::arg("angular_velocity") = origin, py::arg("keyframes") = py::none(),
      py::arg("friction") = defaults.friction, py::arg("tessellation") = defaults.tessellation);
  collider.def_readwrite("name", &ColliderDesc::name, "The collider's name (distinct in a scene).")
      .def_readwrite("friction", &ColliderDesc::friction, "Coulomb friction coefficient, >= 0.")
      .def_readwrite("tessellation", &ColliderDesc::tessellation,
                     "Subdivision level of the collider's surface.")
      .def_property_readonly(
          "shape", [](const ColliderDesc& c) { return shape_name(c.shape); },
          "'sphere', 'box', 'capsule', 'plane' or 'mesh'.")
      .def_property_readonly(
          "moving", [](const ColliderDesc& c) { return moves(c.motion); },
          "Whether its motion ever changes its pose.")
      .def_property_readonly(
          "position",
          [](const ColliderDesc& c) { return vec3_to_array(pose_at(c.motion, 0.0).position); },
          "Where its origin is at t = 0 (m), a (3,) array.")
      .def_property_readonly(
          "rotation",
          [](const ColliderDesc& c) { return quat_to_array(pose_at(c.motion, 0.0).rotation); },
          "Its rotation at t = 0, (w, x, y, z).")
      .def_property_readonly(
          "velocity",
          [](const ColliderDesc& c) {
            return vec3_to_array(scripted(c) ? scripted(c)->linear_velocity : Vec3::Zero());
          },
          "Scripted linear velocity (m/s); zeros for a keyframed collider.")
      .def_property_readonly(
          "angular_velocity",
          [](const ColliderDesc& c) {
            return vec3_to_array(scripted(c) ? scripted(c)->angular_velocity : Vec3::Zero());
          },
          "Scripted angular velocity (rad/s, world axes); zeros for a keyframed collider.")
      .def_property_readonly(
          "keyframes",
          [](const ColliderDesc& c) {
            py::list out;
            if (const auto* k = std::get_if<KeyframedMotion>(&c.motion)) {
              for (const Keyframe& f : k->keyframes)
                out.append(
                    py::make_tuple(f.time, vec3_to_array(f.position), quat_to_array(f.rotation)));
            }
            return out;
          },
          "The keyframes as (time, position, rotation) tuples; empty for a scripted collider.")
      .def(
          "pose_at",
          [](const ColliderDesc& c, double t) {
            if (!std::isfinite(t)) raise("time must be finite, got " + repr_number(t));
            const RigidPose pose = pose_at(c.motion, t);
            return py::make_tuple(vec3_to_array(pose.position), quat_to_array(pose.rotation));
          },
          "(position, rotation) of its origin at time t (s) along its motion.", py::arg("t"))
      .def("__repr__", &repr_collider);
  (void)motion;

  py::class_<GroundDesc>(m, "Ground",
                         "The infinite ground plane y = height (m): the cloth stays above it.")
      .def(py::init([](double height, double friction) {
             GroundDesc g{height, friction};
             if (!std::isfinite(height))
               raise("ground height must be finite, got " + repr_number(height));
             if (!std::isfinite(friction) || friction < 0)
               raise("ground friction must be finite and >= 0, got " + repr_number(friction));
             return g;
           }),
           "Raises animkit.Error for a non-finite height or a negative friction.",
           py::arg("height") = GroundDesc{}.height, py::arg("friction") = GroundDesc{}.friction)
      .def_readwrite("height", &GroundDesc::height, "World y of the plane, m.")
      .def_readwrite("friction", &GroundDesc::friction, "Coulomb coefficient, >= 0.")
      .def("__repr__", [](const GroundDesc& g) {
        return "Ground(height=" + repr_number(g.height) + ", friction=" + repr_number(g.friction) +
               ")";
      });

  py::class_<ContactSettings>(
      m, "ContactSettings",
      "Contact between the cloth and colliders, ground and itself (Incremental Potential "
      "Contact: a log barrier within `thickness`, continuous collision detection).")
      .def(py::init(
               [](double thickness, double stiffness, bool self_contact, double min_separation) {
                 ContactSettings s{thickness, stiffness, self_contact, min_separation};
                 check(s.validate());
                 return s;
               }),
           "Raises animkit.Error for an out-of-range value.",
           py::arg("thickness") = ContactSettings{}.thickness,
           py::arg("stiffness") = ContactSettings{}.stiffness,
           py::arg("self_contact") = ContactSettings{}.self_contact,
           py::arg("min_separation") = ContactSettings{}.min_separation)
      .def_readwrite("thickness", &ContactSettings::thickness,
                     "Barrier activation distance dhat, m, > 0.")
      .def_readwrite("stiffness", &ContactSettings::stiffness,
                     "Barrier stiffness kappa, J/m^4; 0 picks it from the cloth's mass.")
      .def_readwrite("self_contact", &ContactSettings::self_contact,
                     "Whether the cloth also repels itself.")
      .def_readwrite("min_separation", &ContactSettings::min_separation,
                     "Fraction of a pair's distance CCD keeps, in (0, 1).")
      .def("__repr__", [](const ContactSettings& s) {
        return "ContactSettings(thickness=" + repr_number(s.thickness) +
               ", stiffness=" + repr_number(s.stiffness) +
               ", self_contact=" + (s.self_contact ? "True" : "False") +
               ", min_separation=" + repr_number(s.min_separation) + ")";
      });

  py::class_<AirSettings>(m, "AirSettings",
                          "Wind and air drag on the cloth's triangles (flat-plate drag, taken "
                          "implicitly). Velocities in m/s, world axes.")
      .def(py::init([](py::object wind, py::object gust, double gust_frequency, double density,
                       double normal_drag, double tangential_drag) {
             AirSettings s;
             s.wind.velocity = to_vec3(wind, "wind");
             s.wind.gust = to_vec3(gust, "gust");
             s.wind.gust_frequency = gust_frequency;
             s.density = density;
             s.normal_drag = normal_drag;
             s.tangential_drag = tangential_drag;
             check(s.validate());
             return s;
           }),
           "Raises animkit.Error for a NaN, a negative coefficient or a non-positive gust "
           "frequency.",
           py::arg("wind") = origin, py::arg("gust") = origin,
           py::arg("gust_frequency") = WindSettings{}.gust_frequency,
           py::arg("density") = AirSettings{}.density,
           py::arg("normal_drag") = AirSettings{}.normal_drag,
           py::arg("tangential_drag") = AirSettings{}.tangential_drag)
      .def_property(
          "wind", [](const AirSettings& s) { return vec3_to_array(s.wind.velocity); },
          [](AirSettings& s, py::object v) { s.wind.velocity = to_vec3(v, "wind"); },
          "The steady wind velocity, m/s.")
      .def_property(
          "gust", [](const AirSettings& s) { return vec3_to_array(s.wind.gust); },
          [](AirSettings& s, py::object v) { s.wind.gust = to_vec3(v, "gust"); },
          "The gusts' extra velocity at their peak, m/s.")
      .def_property(
          "gust_frequency", [](const AirSettings& s) { return s.wind.gust_frequency; },
          [](AirSettings& s, double f) { s.wind.gust_frequency = f; }, "Gusts per second, Hz.")
      .def_readwrite("density", &AirSettings::density, "Air density, kg/m^3 (0: no air).")
      .def_readwrite("normal_drag", &AirSettings::normal_drag, "Pressure drag coefficient C_n.")
      .def_readwrite("tangential_drag", &AirSettings::tangential_drag,
                     "Skin friction coefficient C_t.")
      .def("__repr__", [](const AirSettings& s) {
        return "AirSettings(wind=" + repr_vec3(s.wind.velocity) +
               ", gust=" + repr_vec3(s.wind.gust) +
               ", gust_frequency=" + repr_number(s.wind.gust_frequency) +
               ", density=" + repr_number(s.density) +
               ", normal_drag=" + repr_number(s.normal_drag) +
               ", tangential_drag=" + repr_number(s.tangential_drag) + ")";
      });
}

// ---- integrators ----

std::string repr_newton(const NewtonSettings& s) {
  return "NewtonSettings(linear_solver='" + enum_name(s.linear_solver, kSolvers) +
         "', tolerance=" + repr_number(s.tolerance) +
         ", max_iterations=" + std::to_string(s.max_iterations) + ", beta=" + repr_number(s.beta) +
         ", gamma=" + repr_number(s.gamma) +
         ", max_line_search_steps=" + std::to_string(s.max_line_search_steps) + ", projection='" +
         enum_name(s.projection, kProjections) +
         "', record_iterations=" + (s.record_iterations ? "True" : "False") + ")";
}

std::string repr_vbd(const VbdSettings& s) {
  return "VbdSettings(tolerance=" + repr_number(s.tolerance) +
         ", max_iterations=" + std::to_string(s.max_iterations) +
         ", record_iterations=" + (s.record_iterations ? "True" : "False") +
         ", check_interval=" + std::to_string(s.check_interval) +
         ", chebyshev_rho=" + repr_number(s.chebyshev_rho) + ", gamma=" + repr_number(s.gamma) +
         ", max_backtracks=" + std::to_string(s.max_backtracks) + ")";
}

std::string repr_local_global(const LocalGlobalSettings& s) {
  return "LocalGlobalSettings(tolerance=" + repr_number(s.tolerance) +
         ", max_iterations=" + std::to_string(s.max_iterations) +
         ", chebyshev=" + (s.chebyshev ? "True" : "False") +
         ", spectral_radius=" + repr_number(s.spectral_radius) +
         ", chebyshev_delay=" + std::to_string(s.chebyshev_delay) +
         ", monotone=" + (s.monotone ? "True" : "False") +
         ", record_iterations=" + (s.record_iterations ? "True" : "False") + ")";
}

std::string repr_integrator(const IntegratorSettings& settings) {
  return std::visit(
      [](const auto& s) -> std::string {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, NewtonSettings>) return repr_newton(s);
        if constexpr (std::is_same_v<S, VbdSettings>) return repr_vbd(s);
        if constexpr (std::is_same_v<S, LocalGlobalSettings>) return repr_local_global(s);
        return "ExplicitEulerSettings()";
      },
      settings);
}

std::string integrator_list() {
  std::string names;
  for (const IntegratorEntry& entry : cloth_integrators())
    names += (names.empty() ? "" : ", ") + std::string(entry.name);
  return names;
}

// An integrator given as settings or as the registry's name ("implicit-multigrid").
IntegratorSettings to_integrator(const py::handle& value) {
  if (py::isinstance<py::str>(value)) {
    const std::string name = value.cast<std::string>();
    const IntegratorEntry* entry = find_integrator(name);
    if (!entry)
      raise("unknown integrator '" + name + "' (expected one of: " + integrator_list() + ")");
    return entry->defaults;
  }
  if (py::isinstance<NewtonSettings>(value)) return value.cast<NewtonSettings>();
  if (py::isinstance<VbdSettings>(value)) return value.cast<VbdSettings>();
  if (py::isinstance<LocalGlobalSettings>(value)) return value.cast<LocalGlobalSettings>();
  if (py::isinstance<ExplicitEulerSettings>(value)) return value.cast<ExplicitEulerSettings>();
  throw py::type_error(
      "integrator must be NewtonSettings, VbdSettings, LocalGlobalSettings, "
      "ExplicitEulerSettings or an integrator's name");
}

py::object integrator_object(const IntegratorSettings& settings) {
  return std::visit([](const auto& s) { return py::cast(s); }, settings);
}

void bind_integrators(py::module_& m) {
  const NewtonSettings newton;
  py::class_<NewtonSettings>(
      m, "NewtonSettings",
      "Implicit Euler by Newton's method with a backtracking line search (the lab's "
      "integrator). Stops when |grad g| <= tolerance * |grad g| at the prediction.")
      .def(py::init([](const std::string& linear_solver, double tolerance, int max_iterations,
                       double beta, double gamma, int max_line_search_steps,
                       const std::string& projection, bool record_iterations) {
             NewtonSettings s{parse_enum(linear_solver, kSolvers, "linear solver"),
                              tolerance,
                              max_iterations,
                              beta,
                              gamma,
                              max_line_search_steps,
                              parse_enum(projection, kProjections, "Hessian projection"),
                              record_iterations};
             check(s.validate());
             return s;
           }),
           "linear_solver: 'direct', 'pcg' or 'multigrid'; projection: 'when_indefinite' or "
           "'always'. Raises animkit.Error for an unknown name or an out-of-range value.",
           py::arg("linear_solver") = enum_name(newton.linear_solver, kSolvers),
           py::arg("tolerance") = newton.tolerance,
           py::arg("max_iterations") = newton.max_iterations, py::arg("beta") = newton.beta,
           py::arg("gamma") = newton.gamma,
           py::arg("max_line_search_steps") = newton.max_line_search_steps,
           py::arg("projection") = enum_name(newton.projection, kProjections),
           py::arg("record_iterations") = newton.record_iterations)
      .def_property(
          "linear_solver",
          [](const NewtonSettings& s) { return enum_name(s.linear_solver, kSolvers); },
          [](NewtonSettings& s, const std::string& v) {
            s.linear_solver = parse_enum(v, kSolvers, "linear solver");
          },
          "'direct', 'pcg' or 'multigrid'.")
      .def_readwrite("tolerance", &NewtonSettings::tolerance,
                     "Relative gradient tolerance, (0, 1).")
      .def_readwrite("max_iterations", &NewtonSettings::max_iterations,
                     "Newton iterations per substep, >= 1.")
      .def_readwrite("beta", &NewtonSettings::beta, "Line-search shrink factor, (0, 1).")
      .def_readwrite("gamma", &NewtonSettings::gamma, "Armijo constant, (0, 1).")
      .def_readwrite("max_line_search_steps", &NewtonSettings::max_line_search_steps,
                     "Backtracking reductions before giving up, >= 1.")
      .def_property(
          "projection",
          [](const NewtonSettings& s) { return enum_name(s.projection, kProjections); },
          [](NewtonSettings& s, const std::string& v) {
            s.projection = parse_enum(v, kProjections, "Hessian projection");
          },
          "'when_indefinite' or 'always'.")
      .def_readwrite("record_iterations", &NewtonSettings::record_iterations,
                     "Fill StepReport.iterations.")
      .def("__repr__", &repr_newton);

  const VbdSettings vbd;
  py::class_<VbdSettings>(m, "VbdSettings",
                          "Vertex Block Descent: coloured Gauss-Seidel sweeps of per-vertex "
                          "Newton steps on the same incremental potential.")
      .def(py::init([](double tolerance, int max_iterations, bool record_iterations,
                       int check_interval, double chebyshev_rho, double gamma, int max_backtracks) {
             VbdSettings s{tolerance,     max_iterations, record_iterations, check_interval,
                           chebyshev_rho, gamma,          max_backtracks};
             check(s.validate());
             return s;
           }),
           "Raises animkit.Error for an out-of-range value.", py::arg("tolerance") = vbd.tolerance,
           py::arg("max_iterations") = vbd.max_iterations,
           py::arg("record_iterations") = vbd.record_iterations,
           py::arg("check_interval") = vbd.check_interval,
           py::arg("chebyshev_rho") = vbd.chebyshev_rho, py::arg("gamma") = vbd.gamma,
           py::arg("max_backtracks") = vbd.max_backtracks)
      .def_readwrite("tolerance", &VbdSettings::tolerance, "Relative gradient tolerance, (0, 1).")
      .def_readwrite("max_iterations", &VbdSettings::max_iterations, "Sweeps per substep, >= 1.")
      .def_readwrite("record_iterations", &VbdSettings::record_iterations,
                     "Fill StepReport.iterations.")
      .def_readwrite("check_interval", &VbdSettings::check_interval,
                     "Sweeps between stopping tests, >= 1.")
      .def_readwrite("chebyshev_rho", &VbdSettings::chebyshev_rho,
                     "Chebyshev spectral radius estimate, [0, 1); 0: off.")
      .def_readwrite("gamma", &VbdSettings::gamma, "Local Armijo constant, (0, 1).")
      .def_readwrite("max_backtracks", &VbdSettings::max_backtracks,
                     "Halvings of a vertex's step, >= 0.")
      .def("__repr__", &repr_vbd);

  const LocalGlobalSettings lg;
  py::class_<LocalGlobalSettings>(
      m, "LocalGlobalSettings",
      "Implicit Euler by the local/global method (Liu et al. 2013), optionally Chebyshev "
      "accelerated.")
      .def(py::init([](double tolerance, int max_iterations, bool chebyshev, double spectral_radius,
                       int chebyshev_delay, bool monotone, bool record_iterations) {
             LocalGlobalSettings s{tolerance,        max_iterations,  chebyshev,
                                   spectral_radius,  chebyshev_delay, monotone,
                                   record_iterations};
             check(s.validate());
             return s;
           }),
           "Raises animkit.Error for an out-of-range value.", py::arg("tolerance") = lg.tolerance,
           py::arg("max_iterations") = lg.max_iterations, py::arg("chebyshev") = lg.chebyshev,
           py::arg("spectral_radius") = lg.spectral_radius,
           py::arg("chebyshev_delay") = lg.chebyshev_delay, py::arg("monotone") = lg.monotone,
           py::arg("record_iterations") = lg.record_iterations)
      .def_readwrite("tolerance", &LocalGlobalSettings::tolerance,
                     "Relative gradient tolerance, (0, 1).")
      .def_readwrite("max_iterations", &LocalGlobalSettings::max_iterations,
                     "Iterations per substep, >= 1.")
      .def_readwrite("chebyshev", &LocalGlobalSettings::chebyshev, "Chebyshev acceleration.")
      .def_readwrite("spectral_radius", &LocalGlobalSettings::spectral_radius,
                     "Spectral radius estimate, (0, 1).")
      .def_readwrite("chebyshev_delay", &LocalGlobalSettings::chebyshev_delay,
                     "Plain iterations before the acceleration, >= 0.")
      .def_readwrite("monotone", &LocalGlobalSettings::monotone,
                     "Reject accelerated iterates that do not decrease g.")
      .def_readwrite("record_iterations", &LocalGlobalSettings::record_iterations,
                     "Fill StepReport.iterations.")
      .def("__repr__", &repr_local_global);

  py::class_<ExplicitEulerSettings>(
      m, "ExplicitEulerSettings",
      "Explicit (symplectic) Euler, the lab's starting point: no settings of its own; its "
      "substeps (ClothScene.substeps, 0 = 1000) keep it stable.")
      .def(py::init<>(), "No settings.")
      .def("__repr__", [](const ExplicitEulerSettings&) { return "ExplicitEulerSettings()"; });

  m.def(
      "integrator_names",
      [] {
        std::vector<std::string> names;
        for (const IntegratorEntry& entry : cloth_integrators()) names.emplace_back(entry.name);
        return names;
      },
      "The integrators' registry names ('implicit-pcg' first, the default), as the CLI's "
      "--integrator takes them.");
  m.def(
      "integrator_settings",
      [](const std::string& name) { return integrator_object(to_integrator(py::str(name))); },
      "The default settings of the integrator called `name` (see integrator_names()). Raises "
      "animkit.Error for an unknown name.",
      py::arg("name"));
}

// ---- the sheets ----

std::string repr_grid(const GridClothOptions& g) {
  return "GridCloth(cells=" + std::to_string(g.cells) + ", size=" + repr_number(g.size) +
         ", height=" + repr_number(g.height) + ", mass=" + repr_number(g.mass) +
         ", stiffness=" + repr_number(g.stiffness) + ", damping=" + repr_number(g.damping) +
         ", gravity=" + repr_number(g.gravity) +
         ", material=" + (g.material ? repr_material(*g.material) : "None") + ", pins='" +
         enum_name(g.pins, kPins) + "', rotation=" + repr_quat(g.rotation) +
         ", offset=" + repr_vec3(g.offset) + ")";
}

std::string repr_mesh(const MeshClothOptions& o) {
  return "MeshCloth(vertices=<" + std::to_string(o.mesh.vertices.size()) + ">, triangles=<" +
         std::to_string(o.mesh.triangles.size()) + ">, mass=" + repr_number(o.mass) +
         ", stiffness=" + repr_number(o.stiffness) + ", damping=" + repr_number(o.damping) +
         ", gravity=" + repr_number(o.gravity) +
         ", material=" + (o.material ? repr_material(*o.material) : "None") +
         ", warp=" + repr_vec3(o.warp) + ", pins=<" + std::to_string(o.pins.size()) +
         ">, pin_boxes=<" + std::to_string(o.pin_boxes.size()) + ">)";
}

std::vector<Eigen::AlignedBox3d> to_boxes(const py::handle& value) {
  DoubleArray array = as_double_array(value, "pin_boxes");
  if (array.ndim() == 1 && array.shape(0) == 0) return {};
  if (array.ndim() != 2 || array.shape(1) != 6)
    raise("pin_boxes must be an array of shape (k, 6): x0, y0, z0, x1, y1, z1 per box");
  std::vector<Eigen::AlignedBox3d> boxes;
  const auto v = array.unchecked<2>();
  for (py::ssize_t k = 0; k < array.shape(0); ++k) {
    boxes.emplace_back(Vec3(v(k, 0), v(k, 1), v(k, 2)), Vec3(v(k, 3), v(k, 4), v(k, 5)));
  }
  return boxes;
}

void bind_sheets(py::module_& m) {
  py::class_<ClothMaterial>(
      m, "Material",
      "A cloth material in physical units: a sheet made of it gets its particle masses and "
      "stiffnesses from these values and its resolution, so it hangs the same at any grid size.")
      .def(py::init(
               [](double density, double stretch, double shear, double bending, double damping) {
                 ClothMaterial mat{density, stretch, shear, bending, damping};
                 check(mat.validate());
                 return mat;
               }),
           "Raises animkit.Error for an out-of-range value.",
           py::arg("density") = ClothMaterial{}.density,
           py::arg("stretch") = ClothMaterial{}.stretch, py::arg("shear") = ClothMaterial{}.shear,
           py::arg("bending") = ClothMaterial{}.bending,
           py::arg("damping") = ClothMaterial{}.damping)
      .def_readwrite("density", &ClothMaterial::density, "Areal density, kg/m^2.")
      .def_readwrite("stretch", &ClothMaterial::stretch, "Membrane stretch stiffness C11, N/m.")
      .def_readwrite("shear", &ClothMaterial::shear, "Membrane shear stiffness C66, N/m.")
      .def_readwrite("bending", &ClothMaterial::bending, "Bending stiffness B, N m.")
      .def_readwrite("damping", &ClothMaterial::damping, "Spring dashpot coefficient, N s/m.")
      .def("__repr__", &repr_material);

  m.def(
      "material",
      [](const std::string& name) {
        const MaterialPreset* preset = find_material(name);
        if (!preset)
          raise("unknown material '" + name + "' (expected one of: " + material_names() + ")");
        return preset->material;
      },
      "The material preset called `name` (cotton, silk, denim, leather, rubber), a copy. Raises "
      "animkit.Error for an unknown name.",
      py::arg("name"));
  m.def(
      "material_names",
      [] {
        std::vector<std::string> names;
        for (const MaterialPreset& p : material_presets()) names.emplace_back(p.name);
        return names;
      },
      "The material presets' names.");

  const GridClothOptions grid;
  py::class_<GridClothOptions>(
      m, "GridCloth",
      "An (n+1) x (n+1) grid cloth in the plane y = height spanning `size` along x and z, "
      "pinned by `pins`; defaults: the lab's cloth (11 x 11 particles, mass 1, stiffness 100, "
      "damping 0.2, gravity 0.3). With a Material the sheet is physical (SI units).")
      .def(py::init([](int cells, double size, double height, double mass, double stiffness,
                       double damping, std::optional<double> gravity,
                       std::optional<ClothMaterial> material, const std::string& pins,
                       py::object rotation, py::object offset) {
             GridClothOptions g;
             g.cells = cells;
             g.size = size;
             g.height = height;
             g.mass = mass;
             g.stiffness = stiffness;
             g.damping = damping;
             g.material = material;
             g.gravity = gravity ? *gravity : default_gravity(material);
             g.pins = parse_enum(pins, kPins, "pins");
             g.rotation = to_quat(rotation, "rotation");
             g.offset = to_vec3(offset, "offset");
             check(g.validate());
             return g;
           }),
           "cells: cells per side; size, height: scene units (m with a material); mass, "
           "stiffness, damping: the lab's per-particle parameters (unused with a material); "
           "gravity along -y (None: 9.81 with a material, else 0.3); pins: 'corners', 'edge' or "
           "'none'; rotation (w, x, y, z) about the sheet's centre, then offset. Raises "
           "animkit.Error for an out-of-range value.",
           py::arg("cells") = grid.cells, py::arg("size") = grid.size,
           py::arg("height") = grid.height, py::arg("mass") = grid.mass,
           py::arg("stiffness") = grid.stiffness, py::arg("damping") = grid.damping,
           py::arg("gravity") = py::none(), py::arg("material") = py::none(),
           py::arg("pins") = enum_name(grid.pins, kPins),
           py::arg("rotation") = py::make_tuple(1.0, 0.0, 0.0, 0.0),
           py::arg("offset") = py::make_tuple(0.0, 0.0, 0.0))
      .def_readwrite("cells", &GridClothOptions::cells, "Cells per side, >= 1.")
      .def_readwrite("size", &GridClothOptions::size, "Side length.")
      .def_readwrite("height", &GridClothOptions::height, "y of the sheet's plane.")
      .def_readwrite("mass", &GridClothOptions::mass, "Mass per particle (lab parameters).")
      .def_readwrite("stiffness", &GridClothOptions::stiffness, "Spring stiffness (lab).")
      .def_readwrite("damping", &GridClothOptions::damping, "Spring damping (lab).")
      .def_readwrite("gravity", &GridClothOptions::gravity, "Acceleration along -y.")
      .def_property(
          "material", [](const GridClothOptions& g) { return g.material; },
          [](GridClothOptions& g, std::optional<ClothMaterial> v) { g.material = std::move(v); },
          "A physical Material, or None for the lab's parameters (a copy; assign it back to "
          "change the sheet).")
      .def_property(
          "pins", [](const GridClothOptions& g) { return enum_name(g.pins, kPins); },
          [](GridClothOptions& g, const std::string& v) { g.pins = parse_enum(v, kPins, "pins"); },
          "'corners', 'edge' or 'none'.")
      .def_property(
          "rotation", [](const GridClothOptions& g) { return quat_to_array(g.rotation); },
          [](GridClothOptions& g, py::object v) { g.rotation = to_quat(v, "rotation"); },
          "Rotation about the sheet's centre, (w, x, y, z).")
      .def_property(
          "offset", [](const GridClothOptions& g) { return vec3_to_array(g.offset); },
          [](GridClothOptions& g, py::object v) { g.offset = to_vec3(v, "offset"); },
          "Translation after the rotation.")
      .def("__repr__", &repr_grid);

  const MeshClothOptions mesh;
  py::class_<MeshClothOptions>(
      m, "MeshCloth",
      "A cloth cut from a triangle mesh: particles at its vertices, springs on its edges, "
      "bending across interior edges, pins by vertex index or by box.")
      .def(py::init([](py::object vertices, py::object triangles, double mass, double stiffness,
                       double damping, std::optional<double> gravity,
                       std::optional<ClothMaterial> material, py::object warp,
                       std::vector<int> pins, py::object pin_boxes) {
             MeshClothOptions o;
             o.mesh.vertices = to_vec3s(vertices, "vertices");
             o.mesh.triangles = to_triangles(triangles, "triangles");
             o.mass = mass;
             o.stiffness = stiffness;
             o.damping = damping;
             o.material = material;
             o.gravity = gravity ? *gravity : default_gravity(material);
             o.warp = to_vec3(warp, "warp");
             o.pins = std::move(pins);
             o.pin_boxes = to_boxes(pin_boxes);
             unwrap(make_mesh_cloth(o));  // every check the sheet needs
             return o;
           }),
           "vertices (n, 3) at rest in world space (m with a material), triangles (m, 3) vertex "
           "indices (manifold); mass, stiffness, damping: the lab's parameters (unused with a "
           "material); gravity along -y (None: 9.81 with a material, else 0.3); warp: the "
           "material's warp direction; pins: vertex indices; pin_boxes (k, 6): x0, y0, z0, x1, "
           "y1, z1 of boxes pinning the vertices inside. Raises animkit.Error for an invalid "
           "mesh, pin or value.",
           py::arg("vertices"), py::arg("triangles"), py::arg("mass") = mesh.mass,
           py::arg("stiffness") = mesh.stiffness, py::arg("damping") = mesh.damping,
           py::arg("gravity") = py::none(), py::arg("material") = py::none(),
           py::arg("warp") = py::make_tuple(1.0, 0.0, 0.0), py::arg("pins") = std::vector<int>{},
           py::arg("pin_boxes") = py::list())
      .def_property_readonly(
          "vertices", [](const MeshClothOptions& o) { return vec3s_to_array(o.mesh.vertices); },
          "The rest shape's vertices (n, 3), a copy.")
      .def_property_readonly(
          "triangles",
          [](const MeshClothOptions& o) { return triangles_to_array(o.mesh.triangles); },
          "The triangles (m, 3), a copy.")
      .def_readwrite("mass", &MeshClothOptions::mass, "Mass per particle (lab parameters).")
      .def_readwrite("stiffness", &MeshClothOptions::stiffness, "Spring stiffness (lab).")
      .def_readwrite("damping", &MeshClothOptions::damping, "Spring damping (lab).")
      .def_readwrite("gravity", &MeshClothOptions::gravity, "Acceleration along -y.")
      .def_property(
          "material", [](const MeshClothOptions& o) { return o.material; },
          [](MeshClothOptions& o, std::optional<ClothMaterial> v) { o.material = std::move(v); },
          "A physical Material, or None for the lab's parameters (a copy; assign it back to "
          "change the sheet).")
      .def_property(
          "warp", [](const MeshClothOptions& o) { return vec3_to_array(o.warp); },
          [](MeshClothOptions& o, py::object v) { o.warp = to_vec3(v, "warp"); },
          "The material's warp direction.")
      .def_readwrite("pins", &MeshClothOptions::pins, "Pinned vertex indices (a copy).")
      .def_property_readonly(
          "pin_boxes",
          [](const MeshClothOptions& o) {
            py::array_t<double> out({static_cast<py::ssize_t>(o.pin_boxes.size()), py::ssize_t{6}});
            auto v = out.mutable_unchecked<2>();
            for (std::size_t k = 0; k < o.pin_boxes.size(); ++k) {
              for (int c = 0; c < 3; ++c) {
                v(static_cast<py::ssize_t>(k), c) = o.pin_boxes[k].min()[c];
                v(static_cast<py::ssize_t>(k), c + 3) = o.pin_boxes[k].max()[c];
              }
            }
            return out;
          },
          "The pin boxes (k, 6), a copy.")
      .def("__repr__", &repr_mesh);
}

// ---- scenes ----

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
         ", integrator=" + repr_integrator(d.simulation.integrator) +
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
             if (contact) d.contact = *contact;
             d.air = air;
             if (!integrator.is_none()) d.simulation.integrator = to_integrator(integrator);
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
           "(default), VbdSettings, LocalGlobalSettings, ExplicitEulerSettings or a registry "
           "name (integrator_names()); substeps per step (0: the integrator's default); dt: s "
           "per frame; frames: the run's length; self_friction: mu between parts of the cloth; "
           "friction_passes: friction's lagging passes; material_name: for reports. Raises "
           "animkit.Error naming the first invalid part.",
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
          [](ClothWorldDesc& d, py::object v) { d.simulation.integrator = to_integrator(v); },
          "The integrator's settings (a copy; assign it back to change the scene); accepts a "
          "registry name too.")
      .def_property_readonly(
          "integrator_name",
          [](const ClothWorldDesc& d) {
            return std::string(integrator_entry(d.simulation.integrator).name);
          },
          "The integrator's registry name, e.g. 'implicit-pcg'.")
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
  bind_cloth_simulator(m);
}

}  // namespace animkit::python
