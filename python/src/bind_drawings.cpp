// Bindings of animkit's drawings (filled in by issue 13's work).
#include "bindings.h"

namespace animkit::python {

void bind_drawings(pybind11::module_& /*m*/) {}

}  // namespace animkit::python
