// The conversions the cloth binding files share (cloth_convert.h).
#include "cloth_convert.h"

#include <cmath>
#include <limits>

#include "numpy_convert.h"
#include "python_errors.h"

namespace animkit::python {

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

std::string quoted(const std::string& text) {
  return py::repr(py::str(text)).cast<std::string>();
}

}  // namespace animkit::python
