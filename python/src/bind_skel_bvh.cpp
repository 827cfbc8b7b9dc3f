// BVH clips from Python: read, parse, write, and their skeleton and motion as Skeleton and
// Motion (io/bvh.h, io/bvh_motion.h).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "animkit/core/validation.h"
#include "animkit/io/bvh.h"
#include "animkit/io/bvh_motion.h"
#include "animkit/io/skeleton_gltf.h"
#include "python_errors.h"
#include "skel_bindings.h"

namespace animkit::python {

namespace {

BvhReadOptions read_options(double scale) {
  BvhReadOptions options;
  options.scale = scale;  // read_bvh checks it (finite, > 0) and names the problem
  return options;
}

/// A clip checked before a call the library asserts on (write_bvh, posing).
const BvhClip& valid(const BvhClip& clip) {
  check(clip.validate());
  return clip;
}

BvhClip with_motion(const BvhClip& clip, const SkeletalMotion& motion) {
  if (motion.joint_count != clip.joint_count() || motion.frame_count() != clip.frame_count()) {
    raise("the motion has " + std::to_string(motion.frame_count()) + " frames of " +
          std::to_string(motion.joint_count) + " joints but the clip " +
          std::to_string(clip.frame_count()) + " frames of " + std::to_string(clip.joint_count()));
  }
  BvhClip out = clip;
  out.frame_time = motion.frame_time;
  {
    py::gil_scoped_release release;
    motion_to_bvh(motion, out);
  }
  return out;
}

std::vector<std::vector<std::string>> channel_names(const BvhClip& clip) {
  std::vector<std::vector<std::string>> names;
  names.reserve(clip.channels.size());
  for (const auto& joint : clip.channels) {
    auto& row = names.emplace_back();
    for (BvhChannel c : joint) row.emplace_back(bvh_channel_name(c));
  }
  return names;
}

}  // namespace

void bind_skel_bvh(py::module_& m) {
  py::class_<BvhClip>(m, "BvhClip",
                      "A BVH motion clip as the file holds it: the joint hierarchy, each "
                      "joint's channels and the per-frame channel values.")
      .def_property_readonly(
          "skeleton", [](const BvhClip& c) { return unwrap(build_skeleton(c.skeleton)); },
          "The clip's Skeleton (joints in file order, End Sites included; offsets in file "
          "units times the read scale). Raises animkit.Error if the hierarchy is invalid.")
      .def_property_readonly(
          "motion",
          [](const BvhClip& c) {
            valid(c);
            py::gil_scoped_release release;
            return motion_from_bvh(c);
          },
          "Every frame as a Motion (local rotations and translations; a copy).")
      .def_property_readonly(
          "frame_time", [](const BvhClip& c) { return c.frame_time; }, "Seconds per frame.")
      .def_property_readonly("frame_count", &BvhClip::frame_count, "Number of frames.")
      .def_property_readonly("joint_count", &BvhClip::joint_count,
                             "Number of joints, End Sites included.")
      .def_property_readonly("channel_count", &BvhClip::channel_count,
                             "Number of channels (columns of `values`).")
      .def_property_readonly(
          "names", [](const BvhClip& c) { return c.skeleton.names; },
          "Joint names in file order (End Sites named '<parent>_End').")
      .def_property_readonly(
          "channels", &channel_names,
          "Each joint's channels in file order, as the file names them ('Xposition', ..., "
          "'Zrotation'); an empty list for End Sites.")
      .def_property_readonly(
          "end_sites", [](const BvhClip& c) { return std::vector<bool>(c.end_sites); },
          "Per joint: whether it is an End Site.")
      .def_property_readonly(
          "values",
          [](const BvhClip& c) {
            py::array_t<double> out({static_cast<py::ssize_t>(c.motion.rows()),
                                     static_cast<py::ssize_t>(c.motion.cols())});
            double* data = out.mutable_data();
            for (Eigen::Index f = 0; f < c.motion.rows(); ++f) {
              for (Eigen::Index k = 0; k < c.motion.cols(); ++k) {
                data[f * c.motion.cols() + k] = c.motion(f, k);
              }
            }
            return out;
          },
          "(frames, channel_count) channel values as the file holds them (rotations in "
          "degrees, positions in file units times the read scale), a copy.")
      .def("with_motion", &with_motion, py::arg("motion"),
           "A new clip with the same hierarchy and channels and `motion`'s frames and frame "
           "time (rotations decomposed into each joint's Euler order). Raises animkit.Error "
           "when the motion's frame or joint count differs from the clip's.")
      .def(
          "scaled",
          [](const BvhClip& c, double factor) {
            BvhClip out = c;
            if (auto ok = scale_bvh_clip(out, factor); !ok) raise(ok.error().message);
            return out;
          },
          py::arg("factor"),
          "A new clip with offsets and position channels multiplied by `factor` (> 0; e.g. "
          "1 / the read scale gives the file's own units back). animkit.Error otherwise.")
      .def(
          "to_text", [](const BvhClip& c) { return write_bvh(valid(c)); },
          "The clip as BVH text (what write_bvh writes).")
      .def("__repr__", [](const BvhClip& c) {
        return "BvhClip(joint_count=" + std::to_string(c.joint_count()) +
               ", frame_count=" + std::to_string(c.frame_count()) +
               ", frame_time=" + std::string(py::repr(py::float_(c.frame_time))) + ")";
      });

  m.def(
      "read_bvh",
      [](const std::filesystem::path& path, double scale) {
        return unwrap(read_bvh_file(path, read_options(scale)));
      },
      py::arg("path"), py::arg("scale") = BvhReadOptions{}.scale,
      py::call_guard<py::gil_scoped_release>(),
      "Reads a BVH file; `scale` multiplies offsets and positions (e.g. 0.056444 for CMU's "
      "units to metres). Raises animkit.Error for a missing or malformed file (the message "
      "names the file and line) or a bad scale.");
  m.def(
      "parse_bvh",
      [](std::string_view text, std::string_view name, double scale) {
        return unwrap(read_bvh(text, name, read_options(scale)));
      },
      py::arg("text"), py::arg("name") = "<string>", py::arg("scale") = BvhReadOptions{}.scale,
      "Parses BVH text; `name` starts every error message ('NAME: line N: ...').");
  m.def(
      "write_bvh",
      [](const std::filesystem::path& path, const BvhClip& clip) {
        py::gil_scoped_release release;
        unwrap(write_bvh_file(path, clip));
      },
      py::arg("path"), py::arg("clip"),
      "Writes the clip as a BVH file, whole or not at all. Raises animkit.Error naming the "
      "path when the clip is invalid or the file cannot be written.");
  m.def(
      "write_glb",
      [](const std::filesystem::path& path, const BvhClip& clip, double metres_per_unit) {
        py::gil_scoped_release release;
        unwrap(write_skeleton_glb_file(path, clip, metres_per_unit));
      },
      py::arg("path"), py::arg("clip"), py::arg("metres_per_unit") = 1.0,
      "Writes the clip as glTF 2.0 (.glb): every joint a node with its motion, and a simple "
      "skinned figure, in metres with +Y up. metres_per_unit converts the clip's units (1 for "
      "a clip read with read_bvh(path, scale) in metres; 0.056444 for a CMU file read at "
      "scale 1). Whole or not at all; raises animkit.Error naming the path.");
}

}  // namespace animkit::python
