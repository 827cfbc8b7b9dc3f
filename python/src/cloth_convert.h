#pragma once
// What the cloth binding files share (bind_cloth_*.cpp, bind_cloth.cpp, bind_pictures.cpp):
// reprs of numbers, triangle arrays, enums as strings, the reprs and conversions one file's
// classes need in another's (a scene shows its sheet, colliders and integrator), and the
// registration of each file's classes, called in order by bind_cloth().
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/integrator_settings.h"
#include "animkit/cloth/mesh_cloth.h"
#include "animkit/collision/collider.h"
#include "animkit/core/types.h"
#include "python_errors.h"

namespace animkit::python {

namespace py = pybind11;

/// A number as Python's repr writes it (1e-06, 0.3, 1.0).
std::string repr_number(double value);
/// "(x, y, z)" of a vector, "(w, x, y, z)" of a quaternion.
std::string repr_vec3(const Vec3& v);
std::string repr_quat(const Quat& q);

/// An (m, 3) array of integer vertex indices (any integer or integral float array), or
/// animkit.Error naming `what`.
std::vector<std::array<int, 3>> to_triangles(const py::handle& value, std::string_view what);
/// (m, 3) int32 array, a copy.
py::array_t<int> triangles_to_array(std::span<const std::array<int, 3>> triangles);

/// Python's repr of a string ('corners').
std::string quoted(const std::string& text);

/// An enum value and the string the scene files (and the bindings) call it.
template <class E>
struct Named {
  const char* name;
  E value;
};

/// The value called `text`, or animkit.Error listing the names ("unknown pins 'x' (expected
/// one of: corners, edge, none)").
template <class E, std::size_t N>
E parse_enum(const std::string& text, const Named<E> (&names)[N], std::string_view what) {
  std::string expected;
  for (const auto& named : names) {
    if (text == named.name) return named.value;
    expected += (expected.empty() ? "" : ", ") + std::string(named.name);
  }
  raise("unknown " + std::string(what) + " '" + text + "' (expected one of: " + expected + ")");
}

/// The name of `value` ("?" for one the table lacks).
template <class E, std::size_t N>
std::string enum_name(E value, const Named<E> (&names)[N]) {
  for (const auto& named : names)
    if (named.value == value) return named.name;
  return "?";
}

// bind_cloth_sinks.cpp: ClothSink, PointCacheSink, ObjSink, GltfSink.
void bind_cloth_sinks(py::module_& m);

// bind_cloth_sheets.cpp: Material, GridCloth, MeshCloth.
void bind_sheets(py::module_& m);
std::string repr_grid(const GridClothOptions& g);
std::string repr_mesh(const MeshClothOptions& o);

// bind_cloth_colliders.cpp: Collider, Ground, ContactSettings, AirSettings.
void bind_colliders(py::module_& m);
std::string repr_collider(const ColliderDesc& c);

// bind_cloth_integrators.cpp: NewtonSettings, VbdSettings, LocalGlobalSettings,
// ExplicitEulerSettings.
void bind_integrators(py::module_& m);
std::string repr_integrator(const IntegratorSettings& settings);
/// An integrator given as settings or as the registry's name ("implicit-multigrid").
IntegratorSettings to_integrator(const py::handle& value);
/// The settings as their Python class.
py::object integrator_object(const IntegratorSettings& settings);

}  // namespace animkit::python
