// Bindings of animkit's skeletons (filled in by issue 13's work).
#include "bindings.h"

namespace animkit::python {

void bind_skeletons(pybind11::module_& /*m*/) {}

}  // namespace animkit::python
