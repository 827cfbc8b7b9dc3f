// Bindings of animkit's cloth (filled in by issue 13's work).
#include "bindings.h"

namespace animkit::python {

void bind_cloth(pybind11::module_& /*m*/) {}

}  // namespace animkit::python
