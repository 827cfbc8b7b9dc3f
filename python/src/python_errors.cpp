#include "python_errors.h"

namespace animkit::python {

void register_errors(pybind11::module_& m) {
  // A ValueError: callers that catch the built-in one for bad arguments catch animkit's too.
  auto& error = pybind11::register_exception<BindingError>(m, "Error", PyExc_ValueError);
  error.attr("__module__") = "animkit";
  error.attr("__doc__") =
      "An animkit error: bad input (a NaN, an out-of-range parameter, a malformed file) or a "
      "simulation that diverged. str(e) is the library's message, which names the problem.";
}

}  // namespace animkit::python
