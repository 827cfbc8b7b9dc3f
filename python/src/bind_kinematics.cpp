// Bindings of animkit's kinematics (filled in by issue 13's work).
#include "bindings.h"

namespace animkit::python {

void bind_kinematics(pybind11::module_& /*m*/) {}

}  // namespace animkit::python
