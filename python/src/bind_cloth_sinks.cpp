// Bindings of the library's frame sinks (cloth_run.h): the output formats a ClothSimulator's
// run() hands every frame to, besides Python callables. Each writes its files whole at the end
// of a run that did not diverge, or leaves nothing.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "animkit/io/gltf_sink.h"
#include "animkit/io/obj_sink.h"
#include "animkit/io/point_cache_sink.h"
#include "cloth_convert.h"
#include "numpy_convert.h"
#include "python_errors.h"

namespace animkit::python {
namespace {

// A 4 x 4 (or 3 x 4) affine matrix, row-major as numpy and Blender's Matrix give it.
Eigen::Affine3d to_affine(const py::handle& value) {
  const DoubleArray a = as_double_array(value, "transform");
  if (a.ndim() != 2 || (a.shape(0) != 4 && a.shape(0) != 3) || a.shape(1) != 4) {
    raise("transform must be a 4 x 4 (or 3 x 4) matrix");
  }
  Eigen::Affine3d t = Eigen::Affine3d::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) {
      const double v = a.at(r, c);
      if (!std::isfinite(v)) raise("transform has a non-finite entry");
      t.matrix()(r, c) = v;
    }
  }
  if (a.shape(0) == 4 &&
      (a.at(3, 0) != 0.0 || a.at(3, 1) != 0.0 || a.at(3, 2) != 0.0 || a.at(3, 3) != 1.0)) {
    raise("transform must be affine: its last row 0, 0, 0, 1");
  }
  return t;
}

}  // namespace

void bind_cloth_sinks(py::module_& m) {
  py::class_<ClothSink>(m, "ClothSink",
                        "An output a ClothSimulator's run() writes frame by frame (pass it in "
                        "run(sinks=[...])): PointCacheSink, ObjSink, GltfSink. Its files are "
                        "written whole when a run ends without diverging, or not at all.");
  py::class_<PointCacheSink, ClothSink>(
      m, "PointCacheSink",
      "Every frame's particle positions (the start included) as a PC2 point cache, what "
      "Blender's Mesh Cache modifier reads, and colliders.pc2 beside it for moving colliders.")
      .def(py::init([](const std::filesystem::path& folder, std::string file, bool colliders,
                       py::object transform, double start_frame) {
             PointCacheOptions options;
             options.cloth_file = std::move(file);
             options.colliders = colliders;
             if (!transform.is_none()) options.transform = to_affine(transform);
             if (!(std::abs(start_frame) <= 1e9)) raise("start_frame must be between -1e9 and 1e9");
             options.start_frame = static_cast<float>(start_frame);
             return std::make_unique<PointCacheSink>(folder, std::move(options));
           }),
           py::arg("folder"), py::arg("file") = std::string("cloth.pc2"),
           py::arg("colliders") = true, py::arg("transform") = py::none(),
           py::arg("start_frame") = 0.0,
           "Writes folder/file (and folder/colliders.pc2 when a collider moves and colliders is "
           "True). transform (4 x 4) maps each cloth position before it is written (e.g. into "
           "a Blender object's local space); start_frame is the header's first frame.");
  py::class_<ObjSink, ClothSink>(
      m, "ObjSink", "cloth.obj (the sheet as it starts) and colliders.obj in a folder.")
      .def(py::init<std::filesystem::path>(), py::arg("folder"),
           "Writes folder/cloth.obj and, with colliders, folder/colliders.obj (the start's "
           "shapes) when a run that did not diverge ends; the folder must exist.");
  py::class_<GltfSink, ClothSink>(
      m, "GltfSink",
      "A .glb file (glTF 2.0): the sheet with one morph target per frame and the colliders "
      "with their motion, in metres with +Y up; web viewers, three.js, Godot and Blender open "
      "it.")
      .def(py::init<std::filesystem::path>(), py::arg("path"),
           "Writes the .glb at path, whole, when a run that did not diverge ends (refused "
           "before the first step when its frames would not fit one file).");
}

}  // namespace animkit::python
