// The extension module animkit._animkit; animkit/__init__.py re-exports it as `animkit`.
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "python_errors.h"

PYBIND11_MODULE(_animkit, m) {
  m.doc() =
      "animkit: inverse kinematics (CCD, FABRIK, DLS on chains and skeletons, foot locking) and "
      "mass-spring cloth (implicit Euler, materials, contact), from Python.";
  m.attr("__version__") = ANIMKIT_VERSION;
  animkit::python::register_errors(m);
  animkit::python::bind_kinematics(m);
  animkit::python::bind_drawings(m);
  animkit::python::bind_skeletons(m);
  animkit::python::bind_cloth(m);
  animkit::python::bind_pictures(m);
}
