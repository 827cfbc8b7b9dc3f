// Bindings of the solids a cloth meets: colliders (five shapes, static or moving by velocities
// or keyframes), the ground, contact settings and air.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <variant>

#include "animkit/cloth/cloth_world.h"
#include "cloth_convert.h"
#include "numpy_convert.h"
#include "python_errors.h"

namespace animkit::python {
namespace {

// The library's names (kBarrierHessianNames); animkit.Error for another.
BarrierHessian barrier_hessian_from(const std::string& name) {
  if (const auto hessian = barrier_hessian_named(name)) return *hessian;
  raise("unknown hessian '" + name + "' (expected one of: " + joined_names(kBarrierHessianNames) +
        ")");
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

const ScriptedMotion* scripted(const ColliderDesc& c) {
  return std::get_if<ScriptedMotion>(&c.motion);
}

}  // namespace

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
      "tessellation: the surface's subdivision level (a sphere's only drawn and exported: "
      "contact takes the sphere itself). Raises animkit.Error on any invalid "
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
                     "Subdivision level of the collider's surface (for a sphere, only what is "
                     "drawn and exported: contact takes the sphere itself).")
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
      .def(py::init([](double thickness, double stiffness, bool self_contact, double min_separation,
                       const std::string& hessian) {
             ContactSettings s{thickness, stiffness, self_contact, min_separation,
                               barrier_hessian_from(hessian)};
             check(s.validate());
             return s;
           }),
           "Raises animkit.Error for an out-of-range value or an unknown hessian.",
           py::arg("thickness") = ContactSettings{}.thickness,
           py::arg("stiffness") = ContactSettings{}.stiffness,
           py::arg("self_contact") = ContactSettings{}.self_contact,
           py::arg("min_separation") = ContactSettings{}.min_separation,
           py::arg("hessian") = std::string(barrier_hessian_name(ContactSettings{}.hessian)))
      .def_readwrite("thickness", &ContactSettings::thickness,
                     "Barrier activation distance dhat, m, > 0.")
      .def_readwrite("stiffness", &ContactSettings::stiffness,
                     "Barrier stiffness kappa, J/m^4; 0 picks it from the cloth's mass and the "
                     "colliders' speed.")
      .def_readwrite("self_contact", &ContactSettings::self_contact,
                     "Whether the cloth also repels itself.")
      .def_readwrite("min_separation", &ContactSettings::min_separation,
                     "Fraction of a pair's distance CCD keeps, in (0, 1).")
      .def_property(
          "hessian",
          [](const ContactSettings& s) { return std::string(barrier_hessian_name(s.hessian)); },
          [](ContactSettings& s, const std::string& name) {
            s.hessian = barrier_hessian_from(name);
          },
          "How each pair's barrier Hessian is formed: 'projected' (exact, eigen-projected), "
          "'gauss_newton' (rank one, PSD by construction) or 'adaptive' (Gauss-Newton until "
          "collision detection freezes a step, then projected for the rest of the substep; "
          "projected at once for a pair closer than 1e-3 of the thickness).")
      .def("__repr__", [](const ContactSettings& s) {
        return "ContactSettings(thickness=" + repr_number(s.thickness) +
               ", stiffness=" + repr_number(s.stiffness) +
               ", self_contact=" + (s.self_contact ? "True" : "False") +
               ", min_separation=" + repr_number(s.min_separation) + ", hessian='" +
               std::string(barrier_hessian_name(s.hessian)) + "')";
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

}  // namespace animkit::python
