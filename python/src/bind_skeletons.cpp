// Bindings of animkit's skeletons: Skeleton, SkeletonPose, Motion and forward kinematics here;
// BVH, joint limits, foot locking and tree IK in bind_skel_*.cpp (skel_bindings.h).
#include <pybind11/stl.h>

#include <cmath>
#include <string>

#include "animkit/core/validation.h"
#include "bindings.h"
#include "numpy_convert.h"
#include "python_errors.h"
#include "skel_bindings.h"

namespace animkit::python {

namespace {

constexpr double kUnitTolerance = 1e-6;  // the library's, for unit quaternions

std::string repr_list(const std::vector<int>& values) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) text += ", ";
    text += std::to_string(values[i]);
  }
  return text + "]";
}

Skeleton make_skeleton(std::vector<std::string> names, std::vector<int> parents,
                       const py::object& rest_offsets, const py::object& rest_rotations) {
  SkeletonDesc desc;
  desc.names = std::move(names);
  desc.parents = std::move(parents);
  desc.rest_offsets = to_vec3s(rest_offsets, "rest_offsets");
  if (!rest_rotations.is_none()) desc.rest_rotations = to_quats(rest_rotations, "rest_rotations");
  return unwrap(build_skeleton(desc));
}

/// A (frames, joints, columns) array's data, checked.
DoubleArray clip_array(const py::object& value, std::string_view what, py::ssize_t columns) {
  DoubleArray array = as_double_array(value, what);
  if (array.ndim() != 3 || array.shape(2) != columns) {
    std::string shape = "(";
    for (py::ssize_t d = 0; d < array.ndim(); ++d) {
      if (d) shape += ", ";
      shape += std::to_string(array.shape(d));
    }
    shape += array.ndim() == 1 ? ",)" : ")";
    raise(std::string(what) + " must be an array of shape (frames, joints, " +
          std::to_string(columns) + "), got shape " + shape);
  }
  return array;
}

void check_frame_time(double frame_time) {
  if (!(std::isfinite(frame_time) && frame_time > 0.0)) {
    raise("frame_time must be a number > 0 (seconds), got " + format_number(frame_time));
  }
}

SkeletalMotion make_motion_from(const py::object& rotations, const py::object& translations,
                                double frame_time) {
  const DoubleArray r = clip_array(rotations, "local_rotations", 4);
  const DoubleArray t = clip_array(translations, "local_translations", 3);
  if (r.shape(0) != t.shape(0) || r.shape(1) != t.shape(1)) {
    raise("local_rotations has " + std::to_string(r.shape(0)) + " frames of " +
          std::to_string(r.shape(1)) + " joints but local_translations " +
          std::to_string(t.shape(0)) + " frames of " + std::to_string(t.shape(1)));
  }
  if (r.shape(1) < 1) raise("a motion needs at least 1 joint, got 0");
  check_frame_time(frame_time);
  const auto frames = static_cast<int>(r.shape(0)), joints = static_cast<int>(r.shape(1));
  SkeletalMotion motion = make_motion(joints, frames, frame_time);
  const double* rd = r.data();
  const double* td = t.data();
  for (std::size_t i = 0; i < motion.local_rotations.size(); ++i) {
    motion.local_rotations[i] = Quat(rd[4 * i], rd[4 * i + 1], rd[4 * i + 2], rd[4 * i + 3]);
    motion.local_translations[i] = Vec3(td[3 * i], td[3 * i + 1], td[3 * i + 2]);
  }
  const auto at = [joints](std::size_t i) {
    const auto n = static_cast<std::size_t>(joints);
    return "[" + std::to_string(i / n) + ", " + std::to_string(i % n) + "]";
  };
  for (std::size_t i = 0; i < motion.local_rotations.size(); ++i) {
    const Quat& q = motion.local_rotations[i];
    if (!is_finite(q)) raise("local_rotations" + at(i) + " has a non-finite component");
    if (std::abs(q.norm() - 1.0) > kUnitTolerance) {
      raise("local_rotations" + at(i) + " is not a unit quaternion (norm " +
            format_number(q.norm()) + ")");
    }
    if (!is_finite(motion.local_translations[i])) {
      raise("local_translations" + at(i) + " has a non-finite coordinate");
    }
  }
  return motion;
}

void check_pose_fits(const Skeleton& skeleton, const SkeletonPose& pose) {
  const auto n = static_cast<std::size_t>(skeleton.joint_count());
  if (pose.local_rotations.size() != n || pose.local_translations.size() != n ||
      pose.global_rotations.size() != n || pose.global_positions.size() != n) {
    raise("the pose has " + std::to_string(pose.local_rotations.size()) +
          " joints but the skeleton " + std::to_string(n));
  }
}

/// A pose property setter: same joint count, finite (and unit for rotations).
template <class T>
void set_pose_part(std::vector<T>& part, std::vector<T> values, std::string_view what) {
  if (values.size() != part.size()) {
    raise(std::string(what) + " must have " + std::to_string(part.size()) + " rows (one per " +
          "joint), got " + std::to_string(values.size()));
  }
  if constexpr (std::is_same_v<T, Quat>) {
    check_unit_quats(values, what);
  } else {
    check_finite(values, what);
  }
  part = std::move(values);
}

}  // namespace

Quat to_unit_quat(const py::object& value, std::string_view what) {
  const Quat q = to_quat(value, what);
  check_unit_quats({q}, what);
  return q;
}

void check_unit_quats(const std::vector<Quat>& rotations, std::string_view what) {
  for (std::size_t i = 0; i < rotations.size(); ++i) {
    const Quat& q = rotations[i];
    const std::string where = rotations.size() == 1 && what.find('[') == std::string_view::npos
                                  ? std::string(what)
                                  : std::string(what) + " row " + std::to_string(i);
    if (!is_finite(q)) raise(where + " has a non-finite component");
    if (std::abs(q.norm() - 1.0) > kUnitTolerance) {
      raise(where + " is not a unit quaternion (norm " + format_number(q.norm()) + ")");
    }
  }
}

void check_finite(const std::vector<Vec3>& points, std::string_view what) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!is_finite(points[i])) {
      raise(std::string(what) + " row " + std::to_string(i) + " has a non-finite coordinate");
    }
  }
}

int joint_index(const Skeleton& skeleton, const py::object& joint, std::string_view what) {
  if (py::isinstance<py::str>(joint)) {
    const auto name = joint.cast<std::string>();
    const int index = skeleton.find_joint(name);
    if (index < 0) raise(std::string(what) + ": the skeleton has no joint named '" + name + "'");
    return index;
  }
  if (py::isinstance<py::int_>(joint) && !py::isinstance<py::bool_>(joint)) {
    const auto index = joint.cast<long long>();
    if (index < 0 || index >= skeleton.joint_count()) {
      raise(std::string(what) + ": joint index " + std::to_string(index) + " is out of range [0, " +
            std::to_string(skeleton.joint_count()) + ")");
    }
    return static_cast<int>(index);
  }
  raise(std::string(what) + " must be a joint index (int) or name (str), got " +
        std::string(py::str(py::type::of(joint).attr("__name__"))));
}

py::array_t<double> motion_rotations_array(const SkeletalMotion& motion) {
  py::array_t<double> array({static_cast<py::ssize_t>(motion.frame_count()),
                             static_cast<py::ssize_t>(motion.joint_count), py::ssize_t{4}});
  double* out = array.mutable_data();
  for (std::size_t i = 0; i < motion.local_rotations.size(); ++i) {
    const Quat& q = motion.local_rotations[i];
    out[4 * i] = q.w(), out[4 * i + 1] = q.x(), out[4 * i + 2] = q.y(), out[4 * i + 3] = q.z();
  }
  return array;
}

py::array_t<double> motion_translations_array(const SkeletalMotion& motion) {
  py::array_t<double> array({static_cast<py::ssize_t>(motion.frame_count()),
                             static_cast<py::ssize_t>(motion.joint_count), py::ssize_t{3}});
  double* out = array.mutable_data();
  for (std::size_t i = 0; i < motion.local_translations.size(); ++i) {
    std::copy_n(motion.local_translations[i].data(), 3, out + 3 * i);
  }
  return array;
}

void bind_skel_core(py::module_& m) {
  // Both classes are registered before their methods, so signatures that mention the other
  // (Skeleton.rest_pose) name it in Python terms.
  py::class_<Skeleton> skeleton_class(
      m, "Skeleton",
      "A skeleton: a tree of named joints (parents before children) with rest "
      "offsets and rotations, immutable once built.");
  py::class_<SkeletonPose> pose_class(
      m, "SkeletonPose",
      "A configuration of a skeleton: local rotations and translations "
      "per joint, and the global ones forward kinematics fills in.");
  skeleton_class
      .def(py::init(&make_skeleton), py::arg("names"), py::arg("parents"), py::arg("rest_offsets"),
           py::arg("rest_rotations") = py::none(),
           "Builds a skeleton. names: unique non-empty joint names; parents[i]: the parent's "
           "index, in [0, i), or -1 for a root; rest_offsets (n, 3): each joint's offset from "
           "its parent in the parent's frame (scene units; a root's is its world position); "
           "rest_rotations (n, 4) unit (w, x, y, z) or None (identity). Raises animkit.Error "
           "naming the first problem (sizes, parents, names, non-finite or non-unit values).")
      .def_property_readonly("joint_count", &Skeleton::joint_count, "Number of joints.")
      .def_property_readonly("names", &Skeleton::names, "Joint names, a list of str (a copy).")
      .def_property_readonly("parents", &Skeleton::parents,
                             "Parent index of each joint (-1 for roots), a list of int.")
      .def_property_readonly(
          "rest_offsets", [](const Skeleton& s) { return vec3s_to_array(s.rest_offsets()); },
          "(n, 3) offsets from each joint's parent at rest, in the parent's frame (scene units).")
      .def_property_readonly(
          "rest_rotations", [](const Skeleton& s) { return quats_to_array(s.rest_rotations()); },
          "(n, 4) rest rotations relative to the parent, unit (w, x, y, z).")
      .def_property_readonly(
          "bone_lengths",
          [](const Skeleton& s) {
            return py::array_t<double>(static_cast<py::ssize_t>(s.bone_lengths().size()),
                                       s.bone_lengths().data());
          },
          "(n,) length of the bone from each joint's parent to it (scene units; 0 for roots).")
      .def_property_readonly("leaves", &Skeleton::leaves,
                             "Indices of the joints with no children (end effectors).")
      .def_property_readonly("roots", &Skeleton::roots, "Indices of the joints with no parent.")
      .def(
          "children",
          [](const Skeleton& s, int joint) {
            if (joint < 0 || joint >= s.joint_count()) raise("joint index out of range");
            return std::vector<int>(s.child_list().begin() + s.child_begin()[joint],
                                    s.child_list().begin() + s.child_begin()[joint + 1]);
          },
          py::arg("joint"),
          "Indices of joint `joint`'s children. Raises animkit.Error when "
          "the index is out of range.")
      .def("find_joint", &Skeleton::find_joint, py::arg("name"),
           "Index of the joint named `name`, or -1 when there is none (as the C++ library; "
           "it never raises).")
      .def("rest_pose", &skeleton_rest_pose, "The skeleton at rest, FK already run.")
      .def("__len__", &Skeleton::joint_count)
      .def("__repr__", [](const Skeleton& s) {
        return "Skeleton(joint_count=" + std::to_string(s.joint_count()) +
               ", roots=" + repr_list(s.roots()) + ", leaves=" + repr_list(s.leaves()) + ")";
      });

  pose_class
      .def(py::init(&skeleton_rest_pose), py::arg("skeleton"), "The skeleton's rest pose (FK run).")
      .def_property(
          "local_rotations",
          [](const SkeletonPose& p) { return quats_to_array(p.local_rotations); },
          [](SkeletonPose& p, const py::object& v) {
            set_pose_part(p.local_rotations, to_quats(v, "local_rotations"), "local_rotations");
          },
          "(n, 4) rotation of each joint relative to its parent, unit (w, x, y, z). Setting "
          "checks the shape and unit length (animkit.Error).")
      .def_property(
          "local_translations",
          [](const SkeletonPose& p) { return vec3s_to_array(p.local_translations); },
          [](SkeletonPose& p, const py::object& v) {
            set_pose_part(p.local_translations, to_vec3s(v, "local_translations"),
                          "local_translations");
          },
          "(n, 3) translation of each joint from its parent, in the parent's frame (scene "
          "units; a root's is its world position). Setting checks the shape (animkit.Error).")
      .def_property(
          "global_rotations",
          [](const SkeletonPose& p) { return quats_to_array(p.global_rotations); },
          [](SkeletonPose& p, const py::object& v) {
            set_pose_part(p.global_rotations, to_quats(v, "global_rotations"), "global_rotations");
          },
          "(n, 4) world rotation of each joint (w, x, y, z), as forward_kinematics left it.")
      .def_property(
          "global_positions",
          [](const SkeletonPose& p) { return vec3s_to_array(p.global_positions); },
          [](SkeletonPose& p, const py::object& v) {
            set_pose_part(p.global_positions, to_vec3s(v, "global_positions"), "global_positions");
          },
          "(n, 3) world position of each joint (scene units), as forward_kinematics left it.")
      .def_property_readonly(
          "joint_count", [](const SkeletonPose& p) { return p.local_rotations.size(); },
          "Number of joints.")
      .def(
          "copy", [](const SkeletonPose& p) { return p; }, "An independent copy.")
      .def("__copy__", [](const SkeletonPose& p) { return p; })
      .def(
          "__deepcopy__", [](const SkeletonPose& p, py::dict) { return p; }, py::arg("memo"))
      .def("__repr__", [](const SkeletonPose& p) {
        return "SkeletonPose(joint_count=" + std::to_string(p.local_rotations.size()) + ")";
      });

  m.def(
      "forward_kinematics",
      [](const Skeleton& skeleton, SkeletonPose& pose) -> SkeletonPose& {
        check_pose_fits(skeleton, pose);
        skeleton_forward_kinematics(skeleton, pose);
        return pose;
      },
      py::arg("skeleton"), py::arg("pose"), py::return_value_policy::reference_internal,
      "Fills pose.global_rotations and pose.global_positions from its locals (in place) and "
      "returns the pose. Raises animkit.Error when the pose does not fit the skeleton.");

  py::class_<SkeletalMotion>(m, "Motion",
                             "A motion clip: every frame's local rotations and translations of "
                             "a skeleton's joints, and the time per frame.")
      .def(py::init(&make_motion_from), py::arg("local_rotations"), py::arg("local_translations"),
           py::arg("frame_time") = SkeletalMotion{}.frame_time,
           "A clip from (frames, joints, 4) unit (w, x, y, z) rotations and (frames, joints, 3) "
           "translations (as SkeletonPose's locals); frame_time in seconds (> 0). Raises "
           "animkit.Error for mismatched shapes, non-finite or non-unit values.")
      .def_property_readonly("frame_count", &SkeletalMotion::frame_count, "Number of frames.")
      .def_readonly("joint_count", &SkeletalMotion::joint_count, "Number of joints.")
      .def_property(
          "frame_time", [](const SkeletalMotion& c) { return c.frame_time; },
          [](SkeletalMotion& c, double t) {
            check_frame_time(t);
            c.frame_time = t;
          },
          "Seconds per frame (> 0; animkit.Error otherwise).")
      .def_property_readonly("local_rotations", &motion_rotations_array,
                             "(frames, joints, 4) local rotations (w, x, y, z), a copy.")
      .def_property_readonly("local_translations", &motion_translations_array,
                             "(frames, joints, 3) local translations (scene units), a copy.")
      .def(
          "pose",
          [](const SkeletalMotion& c, int frame, const Skeleton* skeleton) {
            if (frame < 0) frame += c.frame_count();
            if (frame < 0 || frame >= c.frame_count()) {
              raise("frame " + std::to_string(frame) + " is out of range [0, " +
                    std::to_string(c.frame_count()) + ")");
            }
            SkeletonPose pose = identity_pose(c.joint_count);
            c.read_frame(frame, pose);
            if (skeleton) {
              check_pose_fits(*skeleton, pose);
              skeleton_forward_kinematics(*skeleton, pose);
            }
            return pose;
          },
          py::arg("frame"), py::arg("skeleton") = nullptr,
          "Frame `frame` (negative counts from the end) as a SkeletonPose; with a skeleton, "
          "FK is run (globals filled), else the globals are identity / zero. Raises "
          "animkit.Error for a frame out of range or a skeleton of another size.")
      .def(
          "global_positions",
          [](const SkeletalMotion& c, const Skeleton& skeleton) {
            if (c.joint_count != skeleton.joint_count()) {
              raise("the motion has " + std::to_string(c.joint_count) +
                    " joints but the skeleton " + std::to_string(skeleton.joint_count()));
            }
            py::array_t<double> out({static_cast<py::ssize_t>(c.frame_count()),
                                     static_cast<py::ssize_t>(c.joint_count), py::ssize_t{3}});
            double* data = out.mutable_data();
            {
              py::gil_scoped_release release;
              SkeletonPose pose = identity_pose(c.joint_count);
              const std::size_t n = static_cast<std::size_t>(c.joint_count);
              for (int f = 0; f < c.frame_count(); ++f) {
                c.read_frame(f, pose);
                skeleton_forward_kinematics(skeleton, pose);
                for (std::size_t j = 0; j < n; ++j) {
                  std::copy_n(pose.global_positions[j].data(), 3, data + 3 * (f * n + j));
                }
              }
            }
            return out;
          },
          py::arg("skeleton"),
          "(frames, joints, 3) world positions of every joint in every frame (FK over the "
          "clip, without the GIL). Raises animkit.Error when the skeleton's joint count differs.")
      .def("__repr__", [](const SkeletalMotion& c) {
        return "Motion(frame_count=" + std::to_string(c.frame_count()) +
               ", joint_count=" + std::to_string(c.joint_count) +
               ", frame_time=" + std::string(py::repr(py::float_(c.frame_time))) + ")";
      });
}

void bind_skeletons(py::module_& m) {
  bind_skel_core(m);
  bind_skel_limits(m);
  bind_skel_bvh(m);
  bind_skel_foot_lock(m);
  bind_skel_tree_ik(m);
}

}  // namespace animkit::python
