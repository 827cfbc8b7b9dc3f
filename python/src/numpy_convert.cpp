#include "numpy_convert.h"

#include <algorithm>

#include "python_errors.h"

namespace animkit::python {
namespace {

std::string shape_text(const DoubleArray& array) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) {
    if (d > 0) text += ", ";
    text += std::to_string(array.shape(d));
  }
  return text + (array.ndim() == 1 ? ",)" : ")");
}

/// The rows of an (n, columns) array; an empty sequence is zero rows. A lone row is refused
/// rather than guessed to be a list of one.
DoubleArray rows_of(const py::handle& value, std::string_view what, py::ssize_t columns) {
  DoubleArray array = as_double_array(value, what);
  if (array.ndim() == 2 && array.shape(1) == columns) return array;
  if (array.ndim() == 1 && array.shape(0) == 0) return array;  // an empty list: no rows
  raise(std::string(what) + " must be an array of shape (n, " + std::to_string(columns) +
        "), got shape " + shape_text(array));
}

py::ssize_t row_count(const DoubleArray& array) {
  return array.ndim() == 2 ? array.shape(0) : 0;
}

DoubleArray fixed_vector(const py::handle& value, std::string_view what, py::ssize_t size) {
  DoubleArray array = as_double_array(value, what);
  if (array.ndim() != 1 || array.shape(0) != size) {
    raise(std::string(what) + " must be " + std::to_string(size) + " numbers, got shape " +
          shape_text(array));
  }
  return array;
}

}  // namespace

DoubleArray as_double_array(const py::handle& value, std::string_view what) {
  if (value.is_none()) raise(std::string(what) + " must be an array of numbers, got None");
  // The cast to float64 would drop complex numbers' imaginary parts with only a warning.
  if (const py::array any = py::array::ensure(value); !any) {
    PyErr_Clear();  // not an array at all: the cast below says so
  } else if (any.dtype().kind() == 'c') {
    raise(std::string(what) + " must be real numbers, got complex ones");
  }
  DoubleArray array = DoubleArray::ensure(value);
  if (!array) {
    PyErr_Clear();  // ensure() leaves numpy's conversion error set
    raise(std::string(what) + " must be an array of numbers, got " +
          std::string(py::str(py::type::of(value).attr("__name__"))));
  }
  return array;
}

std::vector<Vec3> to_vec3s(const py::handle& value, std::string_view what) {
  const DoubleArray array = rows_of(value, what, 3);
  std::vector<Vec3> points(static_cast<std::size_t>(row_count(array)));
  const double* data = array.data();
  for (std::size_t i = 0; i < points.size(); ++i) {
    points[i] = Vec3(data[3 * i], data[3 * i + 1], data[3 * i + 2]);
  }
  return points;
}

Vec3 to_vec3(const py::handle& value, std::string_view what) {
  const DoubleArray array = fixed_vector(value, what, 3);
  return Vec3(array.at(0), array.at(1), array.at(2));
}

Quat to_quat(const py::handle& value, std::string_view what) {
  const DoubleArray array = fixed_vector(value, what, 4);
  return Quat(array.at(0), array.at(1), array.at(2), array.at(3));
}

std::vector<Quat> to_quats(const py::handle& value, std::string_view what) {
  const DoubleArray array = rows_of(value, what, 4);
  std::vector<Quat> rotations(static_cast<std::size_t>(row_count(array)));
  const double* data = array.data();
  for (std::size_t i = 0; i < rotations.size(); ++i) {
    rotations[i] = Quat(data[4 * i], data[4 * i + 1], data[4 * i + 2], data[4 * i + 3]);
  }
  return rotations;
}

std::vector<Eigen::Vector2d> to_points2(const py::handle& value, std::string_view what) {
  const DoubleArray array = rows_of(value, what, 2);
  std::vector<Eigen::Vector2d> points(static_cast<std::size_t>(row_count(array)));
  const double* data = array.data();
  for (std::size_t i = 0; i < points.size(); ++i) {
    points[i] = Eigen::Vector2d(data[2 * i], data[2 * i + 1]);
  }
  return points;
}

py::array_t<double> vec3s_to_array(std::span<const Vec3> points) {
  py::array_t<double> array({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}});
  double* out = array.mutable_data();
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::copy_n(points[i].data(), 3, out + 3 * i);
  }
  return array;
}

py::array_t<double> vec3_to_array(const Vec3& point) {
  py::array_t<double> array(py::ssize_t{3});
  std::copy_n(point.data(), 3, array.mutable_data());
  return array;
}

py::array_t<double> quats_to_array(std::span<const Quat> rotations) {
  py::array_t<double> array({static_cast<py::ssize_t>(rotations.size()), py::ssize_t{4}});
  double* out = array.mutable_data();
  for (std::size_t i = 0; i < rotations.size(); ++i) {
    const Quat& q = rotations[i];
    out[4 * i] = q.w();
    out[4 * i + 1] = q.x();
    out[4 * i + 2] = q.y();
    out[4 * i + 3] = q.z();
  }
  return array;
}

py::array_t<double> quat_to_array(const Quat& rotation) {
  py::array_t<double> array(py::ssize_t{4});
  double* out = array.mutable_data();
  out[0] = rotation.w();
  out[1] = rotation.x();
  out[2] = rotation.y();
  out[3] = rotation.z();
  return array;
}

py::array_t<double> points2_to_array(std::span<const Eigen::Vector2d> points) {
  py::array_t<double> array({static_cast<py::ssize_t>(points.size()), py::ssize_t{2}});
  double* out = array.mutable_data();
  for (std::size_t i = 0; i < points.size(); ++i) {
    out[2 * i] = points[i].x();
    out[2 * i + 1] = points[i].y();
  }
  return array;
}

}  // namespace animkit::python
