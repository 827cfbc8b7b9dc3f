#pragma once
// Small conversions the cloth bindings share (bind_cloth.cpp, bind_cloth_simulator.cpp,
// bind_pictures.cpp): reprs of numbers, triangle arrays, enum names.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "animkit/core/types.h"

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

}  // namespace animkit::python
