// Foot locking from Python (kinematics/foot_lock.h): settings, lock_feet over a Motion, and
// its contacts, metrics and ankle trails as numpy arrays.
#include <pybind11/stl.h>

#include <string>

#include "animkit/kinematics/body_scale.h"
#include "animkit/kinematics/foot_lock.h"
#include "cloth_convert.h"
#include "numpy_convert.h"
#include "python_errors.h"
#include "skel_bindings.h"

namespace animkit::python {

namespace {

/// lock_feet's output: the fixed motion beside the library's result.
struct PyFootLockResult {
  FootLockResult result;
  SkeletalMotion motion;
  int frames = 0;
};

KneePole knee_pole_of(const std::string& text) {
  const auto pole = parse_knee_pole(text);
  if (!pole) {
    raise("unknown knee_pole '" + text + "' (expected 'pelvis-forward' or 'original')");
  }
  return *pole;
}

std::string settings_repr(const FootLockSettings& s) {
  return "FootLockSettings(height_threshold=" + repr_number(s.height_threshold) +
         ", speed_threshold=" + repr_number(s.speed_threshold) +
         ", min_contact_frames=" + std::to_string(s.min_contact_frames) +
         ", merge_gap_frames=" + std::to_string(s.merge_gap_frames) +
         ", blend_frames=" + std::to_string(s.blend_frames) +
         ", min_knee_flexion=" + repr_number(s.min_knee_flexion) +
         ", max_knee_flexion=" + repr_number(s.max_knee_flexion) + ", knee_pole='" +
         std::string(to_string(s.knee_pole)) + "', soft_reach=" + repr_number(s.soft_reach) + ")";
}

std::string metrics_repr(const FootLockMetrics& m) {
  return "FootLockMetrics(contacts=(" + std::to_string(m.contacts[0]) + ", " +
         std::to_string(m.contacts[1]) + "), planted_frames=(" +
         std::to_string(m.planted_frames[0]) + ", " + std::to_string(m.planted_frames[1]) +
         "), slide_before_mean_cm=" + repr_number(m.slide_before_mean_cm) +
         ", slide_before_max_cm=" + repr_number(m.slide_before_max_cm) +
         ", slide_after_mean_cm=" + repr_number(m.slide_after_mean_cm) +
         ", slide_after_max_cm=" + repr_number(m.slide_after_max_cm) +
         ", ik_error_mean_cm=" + repr_number(m.ik_error_mean_cm) +
         ", ik_error_max_cm=" + repr_number(m.ik_error_max_cm) +
         ", max_joint_step_before_cm=" + repr_number(m.max_joint_step_before_cm) +
         ", max_joint_step_after_cm=" + repr_number(m.max_joint_step_after_cm) +
         ", max_leg_step_before_cm=" + repr_number(m.max_leg_step_before_cm) +
         ", max_leg_step_after_cm=" + repr_number(m.max_leg_step_after_cm) +
         ", max_correction_step_cm=" + repr_number(m.max_correction_step_cm) +
         ", ms_per_frame=" + repr_number(m.ms_per_frame) + ")";
}

/// The legs a user names: ((hip, knee, ankle), (hip, knee, ankle)) for left and right, each
/// joint an index or a name, checked like find_biped_legs (each the parent of the next).
BipedLegs legs_of(const Skeleton& skeleton, const py::object& legs) {
  if (legs.is_none()) return unwrap(find_biped_legs(skeleton));
  const char* sides[2] = {"left", "right"};
  const char* roles[3] = {"hip", "knee", "ankle"};
  if (!py::isinstance<py::sequence>(legs) || py::isinstance<py::str>(legs) || py::len(legs) != 2) {
    raise("legs must be two (hip, knee, ankle) triples: left, then right");
  }
  BipedLegs out;
  for (int side = 0; side < 2; ++side) {
    const py::object leg = py::reinterpret_borrow<py::sequence>(legs)[side];
    if (!py::isinstance<py::sequence>(leg) || py::isinstance<py::str>(leg) || py::len(leg) != 3) {
      raise(std::string("legs[") + std::to_string(side) + "] (the " + sides[side] +
            " leg) must be a (hip, knee, ankle) triple");
    }
    int joints[3];
    for (int k = 0; k < 3; ++k) {
      joints[k] = joint_index(skeleton, py::reinterpret_borrow<py::sequence>(leg)[k],
                              std::string(sides[side]) + " " + roles[k]);
    }
    for (int k = 1; k < 3; ++k) {
      if (skeleton.parents()[joints[k]] != joints[k - 1]) {
        raise("a biped's leg needs " + skeleton.names()[joints[k - 1]] + " to be the parent of " +
              skeleton.names()[joints[k]]);
      }
    }
    out[side] = LegJoints{joints[0], joints[1], joints[2]};
  }
  return out;
}

PyFootLockResult run_lock(const Skeleton& skeleton, const SkeletalMotion& motion,
                          const FootLockSettings* settings, const py::object& legs) {
  const BipedLegs chosen = legs_of(skeleton, legs);
  const FootLockSettings used = settings ? *settings : FootLockSettings{};
  PyFootLockResult out;
  Result<FootLockResult> result;
  {
    py::gil_scoped_release release;
    FootLockWorkspace workspace;
    result = lock_feet(skeleton, chosen, motion, used, workspace, out.motion);
  }
  out.result = unwrap(std::move(result));
  out.frames = motion.frame_count();
  return out;
}

/// ankles[f * 2 + leg] as an (F, 2, 3) array.
py::array_t<double> ankles_array(const std::vector<Vec3>& ankles) {
  py::array_t<double> out(
      {static_cast<py::ssize_t>(ankles.size() / 2), py::ssize_t{2}, py::ssize_t{3}});
  double* data = out.mutable_data();
  for (std::size_t i = 0; i < ankles.size(); ++i) std::copy_n(ankles[i].data(), 3, data + 3 * i);
  return out;
}

}  // namespace

void bind_skel_foot_lock(py::module_& m) {
  py::class_<FootLockSettings>(m, "FootLockSettings",
                               "Settings of lock_feet: when a foot counts as planted, how "
                               "contacts blend, and the knee's range (metres, seconds, radians).")
      .def(py::init([](double height_threshold, double speed_threshold, int min_contact_frames,
                       int merge_gap_frames, int blend_frames, double min_knee_flexion,
                       double max_knee_flexion, const std::string& knee_pole, double soft_reach) {
             FootLockSettings s;
             s.height_threshold = height_threshold;
             s.speed_threshold = speed_threshold;
             s.min_contact_frames = min_contact_frames;
             s.merge_gap_frames = merge_gap_frames;
             s.blend_frames = blend_frames;
             s.min_knee_flexion = min_knee_flexion;
             s.max_knee_flexion = max_knee_flexion;
             s.knee_pole = knee_pole_of(knee_pole);
             s.soft_reach = soft_reach;
             return s;
           }),
           py::kw_only(), py::arg("height_threshold") = FootLockSettings{}.height_threshold,
           py::arg("speed_threshold") = FootLockSettings{}.speed_threshold,
           py::arg("min_contact_frames") = FootLockSettings{}.min_contact_frames,
           py::arg("merge_gap_frames") = FootLockSettings{}.merge_gap_frames,
           py::arg("blend_frames") = FootLockSettings{}.blend_frames,
           py::arg("min_knee_flexion") = FootLockSettings{}.min_knee_flexion,
           py::arg("max_knee_flexion") = FootLockSettings{}.max_knee_flexion,
           py::arg("knee_pole") = std::string(to_string(FootLockSettings{}.knee_pole)),
           py::arg("soft_reach") = FootLockSettings{}.soft_reach,
           "Settings with the library's defaults; validated when used (lock_feet raises "
           "animkit.Error naming the first bad field). knee_pole: 'pelvis-forward' or "
           "'original' (checked here).")
      .def_readwrite("height_threshold", &FootLockSettings::height_threshold,
                     "Planted when the ankle is at most this high above the clip's lowest "
                     "ankle (metres, > 0).")
      .def_readwrite("speed_threshold", &FootLockSettings::speed_threshold,
                     "... and moves at most this fast (metres per second, > 0).")
      .def_readwrite("min_contact_frames", &FootLockSettings::min_contact_frames,
                     "Shorter planted runs are ignored (frames, >= 1).")
      .def_readwrite("merge_gap_frames", &FootLockSettings::merge_gap_frames,
                     "Planted runs this few frames apart are one contact (>= 0).")
      .def_readwrite("blend_frames", &FootLockSettings::blend_frames,
                     "Frames of smoothstep blend into and out of each contact (>= 0).")
      .def_readwrite("min_knee_flexion", &FootLockSettings::min_knee_flexion,
                     "Least knee flexion on solved frames (radians, >= 0).")
      .def_readwrite("max_knee_flexion", &FootLockSettings::max_knee_flexion,
                     "Most knee flexion on solved frames (radians, <= pi).")
      .def_property(
          "knee_pole",
          [](const FootLockSettings& s) { return std::string(to_string(s.knee_pole)); },
          [](FootLockSettings& s, const std::string& text) { s.knee_pole = knee_pole_of(text); },
          "Where knees point: 'pelvis-forward' or 'original' (animkit.Error otherwise).")
      .def_readwrite("soft_reach", &FootLockSettings::soft_reach,
                     "Soft reach near the straight leg (metres, >= 0; 0: hard).")
      .def(
          "validate", [](const FootLockSettings& s) { check(s.validate()); },
          "Raises animkit.Error naming the first problem, if any.")
      .def("__repr__", &settings_repr);

  py::class_<FootLockMetrics>(m, "FootLockMetrics",
                              "What lock_feet measured: contacts, sliding, IK error and joint "
                              "steps before and after (centimetres), and its wall time.")
      .def_property_readonly(
          "contacts",
          [](const FootLockMetrics& x) { return py::make_tuple(x.contacts[0], x.contacts[1]); },
          "Contact spans per foot, a (left, right) tuple.")
      .def_property_readonly(
          "planted_frames",
          [](const FootLockMetrics& x) {
            return py::make_tuple(x.planted_frames[0], x.planted_frames[1]);
          },
          "Frames inside spans per foot, a (left, right) tuple.")
      .def_readonly("slide_before_mean_cm", &FootLockMetrics::slide_before_mean_cm,
                    "Mean horizontal motion of planted ankles per frame before, cm.")
      .def_readonly("slide_before_max_cm", &FootLockMetrics::slide_before_max_cm,
                    "Largest such motion before, cm.")
      .def_readonly("slide_after_mean_cm", &FootLockMetrics::slide_after_mean_cm,
                    "Mean horizontal motion of planted ankles per frame after, cm.")
      .def_readonly("slide_after_max_cm", &FootLockMetrics::slide_after_max_cm,
                    "Largest such motion after, cm.")
      .def_readonly("ik_error_mean_cm", &FootLockMetrics::ik_error_mean_cm,
                    "Mean |ankle - target| over weighted frames, cm.")
      .def_readonly("ik_error_max_cm", &FootLockMetrics::ik_error_max_cm,
                    "Largest |ankle - target|, cm.")
      .def_readonly("max_joint_step_before_cm", &FootLockMetrics::max_joint_step_before_cm,
                    "Largest move of any joint between frames before, cm.")
      .def_readonly("max_joint_step_after_cm", &FootLockMetrics::max_joint_step_after_cm,
                    "... after, cm.")
      .def_readonly("max_leg_step_before_cm", &FootLockMetrics::max_leg_step_before_cm,
                    "Largest move of a knee, ankle or below between frames before, cm.")
      .def_readonly("max_leg_step_after_cm", &FootLockMetrics::max_leg_step_after_cm,
                    "... after, cm.")
      .def_readonly("max_correction_step_cm", &FootLockMetrics::max_correction_step_cm,
                    "Largest change of any joint's correction between frames, cm.")
      .def_readonly("ms_per_frame", &FootLockMetrics::ms_per_frame,
                    "Wall time of the lock per frame, milliseconds.")
      .def("__repr__", &metrics_repr);

  py::class_<FootContacts>(m, "FootContacts", "One foot's contacts over a clip.")
      .def_property_readonly(
          "planted",
          [](const FootContacts& c) {
            py::array_t<bool> out(static_cast<py::ssize_t>(c.planted.size()));
            for (std::size_t i = 0; i < c.planted.size(); ++i) {
              out.mutable_data()[i] = c.planted[i] != 0;
            }
            return out;
          },
          "(frames,) bool: the frame is inside a contact span.")
      .def_property_readonly(
          "weight",
          [](const FootContacts& c) {
            return py::array_t<double>(static_cast<py::ssize_t>(c.weight.size()), c.weight.data());
          },
          "(frames,) lock weight in [0, 1] (1 planted, smoothstep ramps around spans).")
      .def_property_readonly(
          "lock", [](const FootContacts& c) { return vec3s_to_array(c.lock); },
          "(frames, 3) point the ankle is pulled toward (world, metres; zero where the weight "
          "is 0).")
      .def_property_readonly(
          "spans",
          [](const FootContacts& c) {
            py::list spans;
            for (const FootContactSpan& s : c.spans) {
              spans.append(py::make_tuple(s.first, s.last, vec3_to_array(s.lock)));
            }
            return spans;
          },
          "Contact spans in frame order: (first, last, lock) with inclusive frames and the "
          "ankle's pinned position (3,) (world, metres).")
      .def("__repr__", [](const FootContacts& c) {
        return "FootContacts(frames=" + std::to_string(c.planted.size()) +
               ", spans=" + std::to_string(c.spans.size()) + ")";
      });

  py::class_<PyFootLockResult>(m, "FootLockResult",
                               "What lock_feet returns: the fixed motion, the metrics, each "
                               "foot's contacts and the ankle trails before and after.")
      .def_readonly("motion", &PyFootLockResult::motion, "The foot-locked Motion.")
      .def_property_readonly(
          "metrics", [](const PyFootLockResult& r) { return r.result.metrics; }, "FootLockMetrics.")
      .def_property_readonly(
          "contacts",
          [](const PyFootLockResult& r) {
            return py::make_tuple(r.result.contacts[0], r.result.contacts[1]);
          },
          "(left, right) FootContacts.")
      .def_property_readonly(
          "ankles_before",
          [](const PyFootLockResult& r) { return ankles_array(r.result.ankles_before); },
          "(frames, 2, 3) ankle world positions before (left, right), metres.")
      .def_property_readonly(
          "ankles_after",
          [](const PyFootLockResult& r) { return ankles_array(r.result.ankles_after); },
          "(frames, 2, 3) ankle world positions after (left, right), metres.")
      .def("__repr__", [](const PyFootLockResult& r) {
        return "FootLockResult(frames=" + std::to_string(r.frames) + ", contacts=(" +
               std::to_string(r.result.metrics.contacts[0]) + ", " +
               std::to_string(r.result.metrics.contacts[1]) +
               "), slide_cm=" + repr_number(r.result.metrics.slide_before_mean_cm) + " -> " +
               repr_number(r.result.metrics.slide_after_mean_cm) + ")";
      });

  m.def("lock_feet", &run_lock, py::arg("skeleton"), py::arg("motion"),
        py::arg("settings") = nullptr, py::arg("legs") = py::none(),
        "Foot-locks a biped's motion (metres, Y up): finds where each foot is planted, pins the "
        "ankle there with two-bone leg IK and blends in and out (without the GIL). legs: None "
        "(found by CMU's names LeftHip/LeftKnee/LeftAnkle and Right...) or ((hip, knee, "
        "ankle), (hip, knee, ankle)) left then right, joints by index or name. Raises "
        "animkit.Error for invalid settings, legs, or a motion that does not fit (fewer than "
        "2 frames, another joint count), and when no foot contact is found (with its likely "
        "cause: legs of no human length in metres, or the thresholds).");
  m.def(
      "body_scale",
      [](const Skeleton& skeleton, const py::object& legs) {
        const BodyScale body = unwrap(detect_body_scale(skeleton, legs_of(skeleton, legs)));
        return py::make_tuple(body.unit.metres, std::string(body.unit.name), body.leg_units);
      },
      py::arg("skeleton"), py::arg("legs") = py::none(),
      "The unit a biped's skeleton is in, told from its legs (hip to ankle at rest, nearest an "
      "adult's 0.8 m among metres, centimetres, millimetres, inches and CMU's unit): "
      "(metres per unit, the unit's name, the leg's length in the skeleton's units). legs as "
      "for lock_feet. Raises animkit.Error when no unit gives a leg of 0.4 to 1.3 m.");
}

}  // namespace animkit::python
