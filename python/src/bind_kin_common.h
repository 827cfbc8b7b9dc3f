#pragma once
// What the kinematics and drawings bindings (bind_kinematics.cpp, bind_drawings.cpp,
// bind_kin_render.cpp) share: the Python-side wrappers of a pose and of a drawing run, and
// small helpers for their reprs and arrays.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <span>
#include <string>
#include <vector>

#include "animkit/kinematics/drawing_session.h"
#include "animkit/trajectory/trajectory.h"

namespace animkit::python {

/// A pose and the local offsets of the chain its positions were computed for, so a solve can
/// tell a pose of this chain (used as it is, bit for bit) from one of another chain with the
/// same joint count (re-posed by forward kinematics first).
struct PyPose {
  Pose pose;
  std::vector<Vec3> offsets;
};

/// A drawing session's run and the options it ran with (for summary(), reprs, pictures).
struct PyDrawingRun {
  DrawingRun run;
  DrawingOptions options;
  std::vector<Vec3> chain_offsets;  ///< the chain's local offsets, for final_pose
};

/// A 1-D numpy array of `values` (a copy).
template <class T>
pybind11::array_t<T> to_array(std::span<const T> values) {
  pybind11::array_t<T> array(static_cast<pybind11::ssize_t>(values.size()));
  T* out = array.mutable_data();
  for (std::size_t i = 0; i < values.size(); ++i) out[i] = values[i];
  return array;
}

/// The Trajectory class's pen flags as a numpy bool array.
pybind11::array_t<bool> pen_flags_to_array(std::span<const char> flags);

/// Registers render_png(path, run, ...) (bind_kin_render.cpp); called by bind_drawings.
void bind_kin_render(pybind11::module_& m);

}  // namespace animkit::python
