#pragma once
// The module's parts, one file each, called in this order by module.cpp: a part may use the
// classes an earlier part registered (e.g. skeletons take the kinematics' quaternions).
#include <pybind11/pybind11.h>

namespace animkit::python {

void bind_kinematics(pybind11::module_& m);  ///< chains, the lab's IK solvers, drawing sessions
void bind_drawings(pybind11::module_& m);    ///< shapes, text, images, curves, resampling
void bind_skeletons(pybind11::module_& m);   ///< skeletons, BVH, tree IK, limits, foot locking
void bind_cloth(pybind11::module_& m);       ///< cloth descriptions, scenes, colliders, simulator
void bind_pictures(pybind11::module_& m);    ///< render_png

}  // namespace animkit::python
