#pragma once
// numpy arrays <-> the library's vectors, checked: a wrong shape or dtype raises animkit.Error
// naming the argument and the shape expected, before any solver sees it. Values are copied
// (the library's vectors are std::vector<Vec3>); the cloth state is the one exception, shared
// as read-only views (bind_cloth.cpp). Quaternions are (w, x, y, z), as Blender writes them.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "animkit/core/types.h"

namespace animkit::python {

namespace py = pybind11;
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// `value` as a C-contiguous float64 array (any sequence of numbers converts), or
/// animkit.Error: "<what> must be an array of numbers".
DoubleArray as_double_array(const py::handle& value, std::string_view what);

/// An (n, 3) array of points. Errors name `what` and the shape found.
std::vector<Vec3> to_vec3s(const py::handle& value, std::string_view what);
/// One 3-vector from any sequence of 3 numbers.
Vec3 to_vec3(const py::handle& value, std::string_view what);
/// One quaternion from (w, x, y, z) (not normalized: the library checks unit length).
Quat to_quat(const py::handle& value, std::string_view what);
/// An (n, 4) array of quaternions (w, x, y, z).
std::vector<Quat> to_quats(const py::handle& value, std::string_view what);
/// An (n, 2) array of 2D points.
std::vector<Eigen::Vector2d> to_points2(const py::handle& value, std::string_view what);

/// (n, 3) float64 array, a copy.
py::array_t<double> vec3s_to_array(std::span<const Vec3> points);
/// (3,) float64 array.
py::array_t<double> vec3_to_array(const Vec3& point);
/// (n, 4) float64 array of (w, x, y, z), a copy.
py::array_t<double> quats_to_array(std::span<const Quat> rotations);
/// (4,) float64 array (w, x, y, z).
py::array_t<double> quat_to_array(const Quat& rotation);
/// (n, 2) float64 array, a copy.
py::array_t<double> points2_to_array(std::span<const Eigen::Vector2d> points);

}  // namespace animkit::python
