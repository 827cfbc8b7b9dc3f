// Bindings of animkit's pictures (filled in by issue 13's work).
#include "bindings.h"

namespace animkit::python {

void bind_pictures(pybind11::module_& /*m*/) {}

}  // namespace animkit::python
