// Joint limits from Python: hinge and ball limits as classes, the limits file reader, the
// human defaults, and the swing-twist math (kinematics/joint_limits.h, human_limits.h,
// io/joint_limits_file.h).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <string>

#include "animkit/io/joint_limits_file.h"
#include "animkit/kinematics/human_limits.h"
#include "cloth_convert.h"
#include "numpy_convert.h"
#include "python_errors.h"
#include "skel_bindings.h"

namespace animkit::python {

namespace {

/// An axis as given, scaled to unit length when it is finite and non-zero (as the limits file
/// does); otherwise left for validate() to name.
Vec3 unit_axis(const py::object& value, std::string_view what) {
  Vec3 axis = to_vec3(value, what);
  const double norm = axis.norm();
  if (std::isfinite(norm) && norm > 0.0) axis /= norm;
  return axis;
}

std::string vec_repr(const Vec3& v) {
  return "(" + repr_number(v.x()) + ", " + repr_number(v.y()) + ", " + repr_number(v.z()) + ")";
}

JointLimit to_limit(const py::object& value, std::string_view what) {
  JointLimit limit;
  if (value.is_none() || py::isinstance<FreeJoint>(value)) {
    limit = FreeJoint{};
  } else if (py::isinstance<HingeLimit>(value)) {
    limit = value.cast<HingeLimit>();
  } else if (py::isinstance<BallLimit>(value)) {
    limit = value.cast<BallLimit>();
  } else {
    raise(std::string(what) + " must be a FreeJoint, HingeLimit, BallLimit or None, got " +
          std::string(py::str(py::type::of(value).attr("__name__"))));
  }
  if (auto error = validate(limit)) raise(std::string(what) + ": " + error->message);
  return limit;
}

std::vector<JointLimit> bound_limits(const JointLimitSet& set, const Skeleton& skeleton) {
  return unwrap(bind_joint_limits(set, skeleton.names()));
}

py::list limits_to_list(const std::vector<JointLimit>& limits) {
  py::list list;
  for (const JointLimit& limit : limits) list.append(joint_limit_to_python(limit));
  return list;
}

}  // namespace

std::vector<JointLimit> to_joint_limits(const py::object& limits, const Skeleton& skeleton) {
  if (limits.is_none()) return {};
  if (!py::isinstance<py::sequence>(limits) || py::isinstance<py::str>(limits)) {
    raise("limits must be a list of joint limits (one per joint), got " +
          std::string(py::str(py::type::of(limits).attr("__name__"))));
  }
  const auto list = py::reinterpret_borrow<py::sequence>(limits);
  if (static_cast<int>(list.size()) != skeleton.joint_count()) {
    raise("limits has " + std::to_string(list.size()) + " entries for " +
          std::to_string(skeleton.joint_count()) + " joints");
  }
  std::vector<JointLimit> out;
  out.reserve(list.size());
  for (std::size_t i = 0; i < list.size(); ++i) {
    out.push_back(to_limit(list[i], "limits[" + std::to_string(i) + "]"));
  }
  return out;
}

py::object joint_limit_to_python(const JointLimit& limit) {
  return std::visit([](const auto& l) { return py::cast(l); }, limit);
}

void bind_skel_limits(py::module_& m) {
  py::class_<FreeJoint>(m, "FreeJoint", "No joint limit: every rotation is allowed.")
      .def(py::init<>(), "A free joint.")
      .def("__repr__", [](const FreeJoint&) { return "FreeJoint()"; });

  py::class_<HingeLimit>(m, "HingeLimit",
                         "A hinge joint limit: rotations about one axis (joint's rest frame) by "
                         "an angle in [min_angle, max_angle] radians.")
      .def(py::init([](const py::object& axis, double min_angle, double max_angle) {
             HingeLimit h;
             h.axis = unit_axis(axis, "hinge axis");
             h.min_angle = min_angle;
             h.max_angle = max_angle;
             check(h.validate());
             return h;
           }),
           py::arg("axis") = vec3_to_array(HingeLimit{}.axis),
           py::arg("min_angle") = HingeLimit{}.min_angle,
           py::arg("max_angle") = HingeLimit{}.max_angle,
           "A hinge about `axis` (any non-zero length, normalized) with angles in [min_angle, "
           "max_angle] radians, both in [-pi, pi]. Raises animkit.Error when invalid.")
      .def_property(
          "axis", [](const HingeLimit& h) { return vec3_to_array(h.axis); },
          [](HingeLimit& h, const py::object& v) { h.axis = unit_axis(v, "hinge axis"); },
          "(3,) unit hinge axis in the joint's rest frame (normalized when set).")
      .def_readwrite("min_angle", &HingeLimit::min_angle, "Least angle, radians.")
      .def_readwrite("max_angle", &HingeLimit::max_angle, "Largest angle, radians.")
      .def(
          "validate", [](const HingeLimit& h) { check(h.validate()); },
          "Raises animkit.Error naming the first problem, if any.")
      .def("__repr__", [](const HingeLimit& h) {
        return "HingeLimit(axis=" + vec_repr(h.axis) + ", min_angle=" + repr_number(h.min_angle) +
               ", max_angle=" + repr_number(h.max_angle) + ")";
      });

  py::class_<BallLimit>(m, "BallLimit",
                        "A ball joint limit: the bone swings within a cone (circular, or "
                        "elliptical with swing_angle_2) about its rest direction and twists "
                        "about itself within [min_twist, max_twist]; radians.")
      .def(py::init([](const py::object& twist_axis, double swing_angle, double min_twist,
                       double max_twist, const py::object& swing_axis,
                       std::optional<double> swing_angle_2) {
             BallLimit b;
             b.twist_axis = unit_axis(twist_axis, "ball twist axis");
             b.swing_angle = swing_angle;
             b.min_twist = min_twist;
             b.max_twist = max_twist;
             b.swing_axis = unit_axis(swing_axis, "ball swing axis");
             b.swing_angle_2 = swing_angle_2;
             check(b.validate());
             return b;
           }),
           py::arg("twist_axis") = vec3_to_array(BallLimit{}.twist_axis),
           py::arg("swing_angle") = BallLimit{}.swing_angle,
           py::arg("min_twist") = BallLimit{}.min_twist,
           py::arg("max_twist") = BallLimit{}.max_twist,
           py::arg("swing_axis") = vec3_to_array(BallLimit{}.swing_axis),
           py::arg("swing_angle_2") = py::none(),
           "A ball limit: twist_axis the bone's rest direction (normalized), swing_angle the "
           "cone's half-angle in [0, pi], twist range in [-pi, pi]; for an elliptical cone "
           "swing_angle_2 (swings about twist_axis x swing_axis) and swing_axis (perpendicular "
           "to twist_axis). Raises animkit.Error when invalid.")
      .def_property(
          "twist_axis", [](const BallLimit& b) { return vec3_to_array(b.twist_axis); },
          [](BallLimit& b, const py::object& v) { b.twist_axis = unit_axis(v, "ball twist axis"); },
          "(3,) unit bone direction at rest, joint's rest frame.")
      .def_readwrite("swing_angle", &BallLimit::swing_angle, "Cone half-angle, radians.")
      .def_readwrite("min_twist", &BallLimit::min_twist, "Least twist, radians.")
      .def_readwrite("max_twist", &BallLimit::max_twist, "Largest twist, radians.")
      .def_property(
          "swing_axis", [](const BallLimit& b) { return vec3_to_array(b.swing_axis); },
          [](BallLimit& b, const py::object& v) { b.swing_axis = unit_axis(v, "ball swing axis"); },
          "(3,) elliptical cones: the swing axis whose half-angle is swing_angle.")
      .def_readwrite("swing_angle_2", &BallLimit::swing_angle_2,
                     "Elliptical cones: the other half-angle (radians); None for a circle.")
      .def(
          "validate", [](const BallLimit& b) { check(b.validate()); },
          "Raises animkit.Error naming the first problem, if any.")
      .def("__repr__", [](const BallLimit& b) {
        return "BallLimit(twist_axis=" + vec_repr(b.twist_axis) +
               ", swing_angle=" + repr_number(b.swing_angle) +
               ", min_twist=" + repr_number(b.min_twist) +
               ", max_twist=" + repr_number(b.max_twist) +
               ", swing_axis=" + vec_repr(b.swing_axis) +
               ", swing_angle_2=" + (b.swing_angle_2 ? repr_number(*b.swing_angle_2) : "None") +
               ")";
      });

  m.def(
      "constrain",
      [](const py::object& limit, const py::object& q) {
        return quat_to_array(constrain(to_limit(limit, "limit"), to_unit_quat(q, "q")));
      },
      py::arg("limit"), py::arg("q"),
      "The rotation inside `limit` nearest to the unit quaternion q (w, x, y, z), relative to "
      "the joint's rest rotation; q itself when inside. Raises animkit.Error for an invalid "
      "limit or a non-unit q.");
  m.def(
      "violation",
      [](const py::object& limit, const py::object& q) {
        return violation(to_limit(limit, "limit"), to_unit_quat(q, "q"));
      },
      py::arg("limit"), py::arg("q"),
      "How far the unit quaternion q is beyond `limit`, radians (0 inside).");
  m.def(
      "swing_twist",
      [](const py::object& q, const py::object& axis) {
        const Vec3 a = to_vec3(axis, "axis");
        if (!(std::isfinite(a.norm()) && std::abs(a.norm() - 1.0) <= 1e-6)) {
          raise("axis must be a finite unit vector");
        }
        const SwingTwist st = swing_twist(to_unit_quat(q, "q"), a);
        return py::make_tuple(quat_to_array(st.swing), quat_to_array(st.twist));
      },
      py::arg("q"), py::arg("axis"),
      "Swing-twist decomposition q = swing * twist about the unit `axis`: (swing, twist), "
      "each (4,) (w, x, y, z) with w >= 0.");
  m.def(
      "read_joint_limits",
      [](const std::filesystem::path& path, const Skeleton& skeleton) {
        auto set = unwrap(read_joint_limits_file(path));
        return limits_to_list(bound_limits(set, skeleton));
      },
      py::arg("path"), py::arg("skeleton"),
      "One limit per joint of `skeleton` from a JSON limits file (keyed by joint name, angles "
      "in degrees); FreeJoint where the file says nothing. Raises animkit.Error for a "
      "missing or malformed file or a name no joint has.");
  m.def(
      "parse_joint_limits",
      [](std::string_view text, const Skeleton& skeleton, std::string_view name) {
        auto set = unwrap(read_joint_limits(text, name));
        return limits_to_list(bound_limits(set, skeleton));
      },
      py::arg("text"), py::arg("skeleton"), py::arg("name") = "<string>",
      "read_joint_limits from JSON text; `name` starts every error message.");
  m.def(
      "human_joint_limits",
      [](const Skeleton& skeleton, const SkeletalMotion* motion) {
        std::vector<JointLimit> limits = human_joint_limits(skeleton);
        if (motion) check(fit_hinge_axes(skeleton, *motion, limits));
        return limits_to_list(limits);
      },
      py::arg("skeleton"), py::arg("motion") = nullptr,
      "Plausible human limits by joint name (knees and elbows hinges, other non-roots balls, "
      "roots free); with a motion, each hinge's axis is turned to the axis the clip bends it "
      "about (fit_hinge_axes). Raises animkit.Error when the motion does not fit.");
}

}  // namespace animkit::python
