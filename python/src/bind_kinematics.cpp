// Bindings of the lab's chain IK: chains (the lab's arm or any other), poses and forward
// kinematics, one solve with CCD or FABRIK, and drawing sessions (one solve per target, as the
// lab's app and `animkit ik` run them) with their per-frame records as numpy arrays.
#include <pybind11/stl.h>

#include <cmath>
#include <string>
#include <vector>

#include "animkit/core/quote.h"
#include "animkit/core/validation.h"
#include "animkit/kinematics/chain.h"
#include "animkit/kinematics/drawing_session.h"
#include "animkit/kinematics/forward_kinematics.h"
#include "animkit/kinematics/ik_solver.h"
#include "bind_kin_common.h"
#include "bindings.h"
#include "cloth_convert.h"
#include "numpy_convert.h"
#include "python_errors.h"

namespace animkit::python {

namespace py = pybind11;

py::array_t<bool> pen_flags_to_array(std::span<const char> flags) {
  py::array_t<bool> array(static_cast<py::ssize_t>(flags.size()));
  bool* out = array.mutable_data();
  for (std::size_t i = 0; i < flags.size(); ++i) out[i] = flags[i] != 0;
  return array;
}

namespace {

/// What one solve() did, with the pose it left.
struct PyIkResult {
  IkResult result;
  PyPose pose;
};

std::string vec3_repr(const Vec3& v) {
  return "(" + repr_number(v.x()) + ", " + repr_number(v.y()) + ", " + repr_number(v.z()) + ")";
}

std::string bool_repr(bool value) {
  return value ? "True" : "False";
}

IkSolverKind solver_kind(const std::string& name) {
  if (const auto kind = parse_ik_solver(name)) return *kind;
  std::string names;
  for (IkSolverKind kind : all_ik_solvers()) {
    names += (names.empty() ? "" : " or ") + std::string(to_string(kind));
  }
  raise("unknown solver " + quote_input(name) + " (expected " + names + ")");
}

FabrikRotations fabrik_rotations_kind(const std::string& name) {
  if (const auto mode = parse_fabrik_rotations(name)) return *mode;
  raise("unknown fabrik_rotations " + quote_input(name) + " (expected rest or previous)");
}

IkOptions ik_options(int max_iterations, double tolerance, const std::string& fabrik_rotations) {
  IkOptions options;
  options.max_iterations = max_iterations;
  options.tolerance = tolerance;
  options.fabrik_rotations = fabrik_rotations_kind(fabrik_rotations);
  check(options.validate());
  return options;
}

PyPose pose_of(const Chain& chain, const py::object& local_rotations) {
  if (local_rotations.is_none()) return {rest_pose(chain), chain.local_offsets()};
  std::vector<Quat> rotations = to_quats(local_rotations, "local_rotations");
  const std::size_t n = chain.local_offsets().size();
  if (rotations.size() != n) {
    raise("local_rotations has " + std::to_string(rotations.size()) + " rotations for a chain of " +
          std::to_string(n) + " joints");
  }
  for (std::size_t i = 0; i < n; ++i) {
    // The solvers' own check (ik_solver.cpp): finite, |q|^2 within 1e-6 of 1.
    if (!is_finite(rotations[i]) || std::abs(rotations[i].squaredNorm() - 1.0) > 1e-6) {
      raise("local_rotations joint " + std::to_string(i) +
            " is not a finite unit quaternion (w, x, y, z)");
    }
  }
  Pose pose{std::move(rotations), std::vector<Quat>(n, Quat::Identity()),
            std::vector<Vec3>(n, Vec3::Zero())};
  forward_kinematics(chain, pose, 0);
  return {std::move(pose), chain.local_offsets()};
}

/// `pose` made a valid start for `chain`: the same joint count, and positions computed with
/// this chain's offsets (a pose of another chain is re-posed by forward kinematics; a pose of
/// this one is left bit for bit as it is, so chained solves reproduce a drawing session).
void fit_pose_to(PyPose& pose, const Chain& chain) {
  const std::size_t n = chain.local_offsets().size();
  if (pose.pose.local_rotations.size() != n) {
    raise("pose has " + std::to_string(pose.pose.local_rotations.size()) +
          " joints but the chain has " + std::to_string(n));
  }
  if (pose.offsets != chain.local_offsets()) {
    forward_kinematics(chain, pose.pose, 0);
    pose.offsets = chain.local_offsets();
  }
}

std::vector<char> pen_flags(const py::object& value) {
  const DoubleArray array = as_double_array(value, "pen_down");
  if (array.ndim() != 1) {
    raise("pen_down must be a 1-D array of flags (one per target), got " +
          std::to_string(array.ndim()) + " dimensions");
  }
  std::vector<char> flags(static_cast<std::size_t>(array.shape(0)));
  const double* data = array.data();
  for (std::size_t i = 0; i < flags.size(); ++i) {
    if (!std::isfinite(data[i])) {
      raise("pen_down " + std::to_string(i) + " is not a finite number");
    }
    flags[i] = data[i] != 0.0 ? 1 : 0;
  }
  return flags;
}

template <class Get>
auto per_frame(const DrawingRun& run, Get get) {
  using T = decltype(get(run.frames.front()));
  std::vector<T> values;
  values.reserve(run.frames.size());
  for (const DrawingFrame& frame : run.frames) values.push_back(get(frame));
  return values;
}

template <class Get>
py::array_t<double> per_frame_points(const DrawingRun& run, Get get) {
  std::vector<Vec3> points;
  points.reserve(run.frames.size());
  for (const DrawingFrame& frame : run.frames) points.push_back(get(frame));
  return vec3s_to_array(points);
}

py::array_t<bool> per_frame_flags(const DrawingRun& run, bool (*get)(const DrawingFrame&)) {
  py::array_t<bool> array(static_cast<py::ssize_t>(run.frames.size()));
  bool* out = array.mutable_data();
  for (std::size_t i = 0; i < run.frames.size(); ++i) out[i] = get(run.frames[i]);
  return array;
}

py::array_t<double> joint_positions_array(const DrawingRun& run) {
  const std::size_t joints = run.frames.empty() ? 0 : run.frames.front().joint_positions.size();
  py::array_t<double> array({static_cast<py::ssize_t>(run.frames.size()),
                             static_cast<py::ssize_t>(joints), py::ssize_t{3}});
  double* out = array.mutable_data();
  for (const DrawingFrame& frame : run.frames) {
    for (const Vec3& p : frame.joint_positions) {
      out[0] = p.x();
      out[1] = p.y();
      out[2] = p.z();
      out += 3;
    }
  }
  return array;
}

std::string summary_repr(const DrawingSummary& s) {
  return "DrawingSummary(targets=" + std::to_string(s.targets) +
         ", converged_fraction=" + repr_number(s.converged_fraction) +
         ", unreachable_targets=" + std::to_string(s.unreachable_targets) +
         ", iterations_mean=" + repr_number(s.iterations_mean) +
         ", iterations_median=" + repr_number(s.iterations_median) +
         ", iterations_max=" + std::to_string(s.iterations_max) +
         ", error_mean=" + repr_number(s.error_mean) + ", error_max=" + repr_number(s.error_max) +
         ", max_joint_step_rad=" + repr_number(s.max_joint_step_rad) +
         ", solve_time_us_median=" + repr_number(s.solve_time_us_median) +
         ", solve_time_us_mean=" + repr_number(s.solve_time_us_mean) + ")";
}

void bind_chain(py::module_& m) {
  py::class_<Chain>(m, "Chain",
                    "An immutable kinematic chain: joints 0..n-1 in a line, joint 0 the root.\n\n"
                    "Built once from its rest offsets (and rest rotations); many poses share it.")
      .def(py::init([](const py::object& offsets, const py::object& rotations) {
             ChainDesc desc;
             desc.local_offsets = to_vec3s(offsets, "offsets");
             if (!rotations.is_none()) desc.local_rotations = to_quats(rotations, "rotations");
             return unwrap(build_chain(desc));
           }),
           py::arg("offsets"), py::arg("rotations") = py::none(),
           "Builds a chain from its rest description.\n\n"
           "offsets: (n, 3) translations of joint i from its parent in the parent's rest frame\n"
           "(offsets[0] is the root's world position), n >= 2; every offset from 1 on is a bone\n"
           "and must have non-zero length. rotations: None (identity) or (n, 4) unit\n"
           "quaternions (w, x, y, z), joint i's rest rotation relative to its parent.\n"
           "Raises animkit.Error naming the first problem ('bone 3 has zero length').")
      .def_static(
          "lab_arm", [] { return unwrap(build_chain(lab_arm())); },
          "The lab's robot arm (Y up): joints at rest at (0,1.7,0), (0,0.9,0), (0,0.5,0),\n"
          "(0,0.3,0), (0,-0.9,0); bones 0.8, 0.4, 0.2, 1.2 (reach 2.6).")
      .def_static(
          "from_rest_positions",
          [](const py::object& points) {
            const std::vector<Vec3> positions = to_vec3s(points, "points");
            return unwrap(build_chain(ChainDesc::from_rest_positions(positions)));
          },
          py::arg("points"),
          "A chain whose joints rest at the given (n, 3) world positions, identity rotations.\n"
          "Raises animkit.Error for fewer than 2 joints or two equal consecutive points.")
      .def_property_readonly("joint_count", &Chain::joint_count, "Number of joints (>= 2).")
      .def_property_readonly(
          "bone_lengths", [](const Chain& c) { return to_array<double>(c.bone_lengths()); },
          "(n,) length of the bone from joint i-1 to joint i (scene units); entry 0 is 0.")
      .def_property_readonly("reach", &Chain::reach,
                             "Sum of the bone lengths: the farthest the end effector gets from "
                             "the root (scene units).")
      .def_property_readonly("min_reach", &Chain::min_reach,
                             "The nearest the end effector gets to the root: max(0, 2 * longest "
                             "bone - reach) (scene units).")
      .def_property_readonly(
          "root_position", [](const Chain& c) { return vec3_to_array(c.root_position()); },
          "(3,) the root joint's world position.")
      .def_property_readonly(
          "local_offsets", [](const Chain& c) { return vec3s_to_array(c.local_offsets()); },
          "(n, 3) rest offsets of each joint from its parent (offsets[0]: the root's position).")
      .def_property_readonly(
          "rest_rotations", [](const Chain& c) { return quats_to_array(c.rest_rotations()); },
          "(n, 4) rest rotations (w, x, y, z), each relative to its parent, unit length.")
      .def("__repr__", [](const Chain& c) {
        return "Chain(joint_count=" + std::to_string(c.joint_count()) +
               ", reach=" + repr_number(c.reach()) +
               ", root_position=" + vec3_repr(c.root_position()) + ")";
      });
}

void bind_pose(py::module_& m) {
  py::class_<PyPose>(m, "Pose",
                     "A configuration of a chain (immutable): per-joint local rotations and the\n"
                     "world rotations and positions forward kinematics gives for them.")
      .def(py::init(&pose_of), py::arg("chain"), py::arg("local_rotations") = py::none(),
           "The pose of `chain` with these (n, 4) local rotations (w, x, y, z), each relative\n"
           "to its parent, by forward kinematics; None: the rest pose. Raises animkit.Error\n"
           "for a wrong count or a rotation that is not a finite unit quaternion.")
      .def_property_readonly(
          "joint_count",
          [](const PyPose& p) { return static_cast<int>(p.pose.local_rotations.size()); },
          "Number of joints.")
      .def_property_readonly(
          "local_rotations", [](const PyPose& p) { return quats_to_array(p.pose.local_rotations); },
          "(n, 4) rotation of each joint relative to its parent (w, x, y, z); a copy.")
      .def_property_readonly(
          "global_rotations",
          [](const PyPose& p) { return quats_to_array(p.pose.global_rotations); },
          "(n, 4) world rotation of each joint (w, x, y, z); a copy.")
      .def_property_readonly(
          "global_positions",
          [](const PyPose& p) { return vec3s_to_array(p.pose.global_positions); },
          "(n, 3) world position of each joint (scene units); a copy.")
      .def_property_readonly(
          "end_effector", [](const PyPose& p) { return vec3_to_array(p.pose.end_effector()); },
          "(3,) world position of the last joint.")
      .def("__repr__", [](const PyPose& p) {
        return "Pose(joint_count=" + std::to_string(p.pose.local_rotations.size()) +
               ", end_effector=" + vec3_repr(p.pose.end_effector()) + ")";
      });

  m.def(
      "rest_pose", [](const Chain& chain) { return pose_of(chain, py::none()); }, py::arg("chain"),
      "The chain at rest (its rest rotations), forward kinematics run.");
  m.def("forward_kinematics", &pose_of, py::arg("chain"), py::arg("local_rotations"),
        "Forward kinematics: the Pose of `chain` with these (n, 4) local rotations (w, x, y, z).\n"
        "global_rotation[i] = global_rotation[i-1] * local_rotation[i];\n"
        "global_position[i] = global_position[i-1] + global_rotation[i-1] * offset[i].\n"
        "Raises animkit.Error for a wrong count or a non-unit rotation.");
}

void bind_solve(py::module_& m) {
  py::class_<PyIkResult>(m, "IkResult",
                         "What one IK solve did, and the pose it left (the start is untouched).")
      .def_property_readonly(
          "iterations", [](const PyIkResult& r) { return r.result.iterations; },
          "Full iterations run (a CCD sweep, a FABRIK backward + forward pass).")
      .def_property_readonly(
          "error", [](const PyIkResult& r) { return r.result.error; },
          "|end effector - target| after the solve (scene units).")
      .def_property_readonly(
          "converged", [](const PyIkResult& r) { return r.result.converged; },
          "True when error <= tolerance.")
      .def_property_readonly(
          "reachable", [](const PyIkResult& r) { return r.result.reachable; },
          "False when no pose reaches the target (beyond the reach or inside the minimum\n"
          "reach); the chain then points straight at it.")
      .def_property_readonly(
          "pose", [](const PyIkResult& r) { return r.pose; },
          "The solved Pose; pass it as the next solve's `pose` to warm-start.")
      .def("__repr__", [](const PyIkResult& r) {
        return "IkResult(iterations=" + std::to_string(r.result.iterations) +
               ", error=" + repr_number(r.result.error) +
               ", converged=" + bool_repr(r.result.converged) +
               ", reachable=" + bool_repr(r.result.reachable) + ")";
      });

  const IkOptions defaults;
  m.def(
      "solve",
      [](const Chain& chain, const py::object& target, const std::string& solver,
         const PyPose* pose, int max_iterations, double tolerance,
         const std::string& fabrik_rotations) {
        const IkSolverKind kind = solver_kind(solver);
        const IkOptions options = ik_options(max_iterations, tolerance, fabrik_rotations);
        const Vec3 point = to_vec3(target, "target");
        PyPose start = pose ? *pose : pose_of(chain, py::none());
        fit_pose_to(start, chain);
        Result<IkResult> result = fail("not solved");
        {
          py::gil_scoped_release release;
          result = solve_ik(kind, chain, start.pose, point, options);
        }
        return PyIkResult{unwrap(std::move(result)), std::move(start)};
      },
      py::arg("chain"), py::arg("target"), py::arg("solver") = "ccd", py::arg("pose") = py::none(),
      py::arg("max_iterations") = defaults.max_iterations,
      py::arg("tolerance") = defaults.tolerance,
      py::arg("fabrik_rotations") = std::string(to_string(defaults.fabrik_rotations)),
      "Solves IK for one (3,) world target with 'ccd' or 'fabrik' and returns an IkResult.\n\n"
      "pose: the start (warm start); None starts from rest. It is copied, never changed: the\n"
      "solution is the result's .pose. max_iterations >= 1; tolerance > 0 (converged when\n"
      "|end effector - target| <= tolerance); fabrik_rotations 'rest' (the lab's) or\n"
      "'previous' (FABRIK only). Raises animkit.Error for a NaN/inf or huge target, a pose\n"
      "with another joint count, bad options or an unknown solver name.");

  m.def(
      "ik_solver_names",
      [] {
        std::vector<std::string> names;
        for (IkSolverKind kind : all_ik_solvers()) names.emplace_back(to_string(kind));
        return names;
      },
      "The chain IK solvers' names, in menu order: ['ccd', 'fabrik'].");
  m.def(
      "fabrik_rotation_names",
      [] {
        return std::vector<std::string>{std::string(to_string(FabrikRotations::from_rest)),
                                        std::string(to_string(FabrikRotations::from_previous))};
      },
      "How FABRIK can recover joint rotations: ['rest', 'previous'].");
}

void bind_drawing_run(py::module_& m) {
  py::class_<DrawingSummary>(m, "DrawingSummary",
                             "Aggregate numbers of a drawing run (what `animkit ik` writes to "
                             "metrics.json).")
      .def_readonly("targets", &DrawingSummary::targets, "Frames solved (laps x targets).")
      .def_readonly("converged_fraction", &DrawingSummary::converged_fraction,
                    "Fraction of frames with error <= tolerance, in [0, 1].")
      .def_readonly("unreachable_targets", &DrawingSummary::unreachable_targets,
                    "Frames whose target no pose reaches.")
      .def_readonly("iterations_mean", &DrawingSummary::iterations_mean,
                    "Mean iterations per frame.")
      .def_readonly("iterations_median", &DrawingSummary::iterations_median,
                    "Median iterations per frame.")
      .def_readonly("iterations_max", &DrawingSummary::iterations_max,
                    "Most iterations of any frame.")
      .def_readonly("error_mean", &DrawingSummary::error_mean,
                    "Mean |end effector - target| after the solves (scene units).")
      .def_readonly("error_max", &DrawingSummary::error_max,
                    "Largest |end effector - target| (scene units).")
      .def_readonly("max_joint_step_rad", &DrawingSummary::max_joint_step_rad,
                    "Largest frame-to-frame change of any joint's local rotation (radians): the "
                    "jitter.")
      .def_readonly("solve_time_us_median", &DrawingSummary::solve_time_us_median,
                    "Median wall-clock time of a solve (microseconds).")
      .def_readonly("solve_time_us_mean", &DrawingSummary::solve_time_us_mean,
                    "Mean wall-clock time of a solve (microseconds).")
      .def("__repr__", &summary_repr);

  py::class_<PyDrawingRun>(m, "DrawingRun",
                           "A drawing session's record: one frame per solve (laps x targets), as "
                           "numpy arrays (copies).")
      .def_property_readonly(
          "frame_count", [](const PyDrawingRun& r) { return r.run.frames.size(); },
          "Number of frames (laps x targets).")
      .def(
          "__len__", [](const PyDrawingRun& r) { return r.run.frames.size(); }, "Number of frames.")
      .def_property_readonly(
          "iterations",
          [](const PyDrawingRun& r) {
            const auto v = per_frame(
                r.run, [](const DrawingFrame& f) { return std::int64_t{f.ik.iterations}; });
            return to_array<std::int64_t>(v);
          },
          "(frames,) int64 solver iterations of each frame.")
      .def_property_readonly(
          "errors",
          [](const PyDrawingRun& r) {
            return to_array<double>(
                per_frame(r.run, [](const DrawingFrame& f) { return f.ik.error; }));
          },
          "(frames,) |end effector - target| after each solve (scene units).")
      .def_property_readonly(
          "converged",
          [](const PyDrawingRun& r) {
            return per_frame_flags(r.run, [](const DrawingFrame& f) { return f.ik.converged; });
          },
          "(frames,) bool: error <= tolerance.")
      .def_property_readonly(
          "reachable",
          [](const PyDrawingRun& r) {
            return per_frame_flags(r.run, [](const DrawingFrame& f) { return f.ik.reachable; });
          },
          "(frames,) bool: some pose reaches the target.")
      .def_property_readonly(
          "pen_down",
          [](const PyDrawingRun& r) {
            return per_frame_flags(r.run, [](const DrawingFrame& f) { return f.pen_down; });
          },
          "(frames,) bool: the pen draws (False while travelling between strokes).")
      .def_property_readonly(
          "end_effectors",
          [](const PyDrawingRun& r) {
            return per_frame_points(r.run, [](const DrawingFrame& f) { return f.end_effector; });
          },
          "(frames, 3) the end effector after each solve (world).")
      .def_property_readonly(
          "targets",
          [](const PyDrawingRun& r) {
            return per_frame_points(r.run, [](const DrawingFrame& f) { return f.target; });
          },
          "(frames, 3) each frame's target (world).")
      .def_property_readonly(
          "joint_steps",
          [](const PyDrawingRun& r) {
            return to_array<double>(
                per_frame(r.run, [](const DrawingFrame& f) { return f.joint_step_rad; }));
          },
          "(frames,) largest change of any joint's local rotation since the previous frame of\n"
          "the same lap (radians; 0 on a lap's first frame): the jitter.")
      .def_property_readonly(
          "solve_time_us",
          [](const PyDrawingRun& r) {
            return to_array<double>(
                per_frame(r.run, [](const DrawingFrame& f) { return f.solve_time_us; }));
          },
          "(frames,) wall-clock time of each solve (microseconds).")
      .def_property_readonly(
          "laps",
          [](const PyDrawingRun& r) {
            const auto v =
                per_frame(r.run, [](const DrawingFrame& f) { return std::int64_t{f.lap}; });
            return to_array<std::int64_t>(v);
          },
          "(frames,) int64 lap of each frame, from 0.")
      .def_property_readonly(
          "joint_positions", [](const PyDrawingRun& r) { return joint_positions_array(r.run); },
          "(frames, joints, 3) the arm's joint positions after each solve (world).")
      .def_property_readonly(
          "final_pose",
          [](const PyDrawingRun& r) {
            return PyPose{r.run.final_pose, r.chain_offsets};
          },
          "The Pose after the last frame.")
      .def_property_readonly(
          "solver", [](const PyDrawingRun& r) { return std::string(to_string(r.options.solver)); },
          "The solver the run used ('ccd' or 'fabrik').")
      .def_property_readonly(
          "max_iterations", [](const PyDrawingRun& r) { return r.options.ik.max_iterations; },
          "The iteration cap per target.")
      .def_property_readonly(
          "tolerance", [](const PyDrawingRun& r) { return r.options.ik.tolerance; },
          "The convergence tolerance (scene units).")
      .def_property_readonly(
          "fabrik_rotations",
          [](const PyDrawingRun& r) {
            return std::string(to_string(r.options.ik.fabrik_rotations));
          },
          "How FABRIK recovered rotations ('rest' or 'previous').")
      .def_property_readonly(
          "lap_count", [](const PyDrawingRun& r) { return r.options.laps; },
          "Times the target list was drawn.")
      .def_property_readonly(
          "warm_start", [](const PyDrawingRun& r) { return r.options.warm_start; },
          "True when each frame started from the previous frame's pose.")
      .def(
          "summary", [](const PyDrawingRun& r) { return summarize(r.run); },
          "The run's DrawingSummary (converged fraction, iterations, errors, jitter, times).")
      .def(
          "drawn_strokes",
          [](const PyDrawingRun& r) {
            py::list strokes;
            for (const auto& stroke : drawn_strokes(r.run.frames)) {
              strokes.append(vec3s_to_array(stroke));
            }
            return strokes;
          },
          "The drawn path: the end effector while the pen is down, one (k, 3) array per stroke\n"
          "(a new one at each pen-up and each lap).")
      .def("__repr__", [](const PyDrawingRun& r) {
        const DrawingSummary s = summarize(r.run);
        return "DrawingRun(solver='" + std::string(to_string(r.options.solver)) +
               "', frames=" + std::to_string(r.run.frames.size()) +
               ", laps=" + std::to_string(r.options.laps) +
               ", converged_fraction=" + repr_number(s.converged_fraction) +
               ", iterations_mean=" + repr_number(s.iterations_mean) + ")";
      });

  const IkOptions ik_defaults;
  const DrawingOptions defaults;
  m.def(
      "run_drawing",
      [](const Chain& chain, const py::object& targets, const py::object& pen_down,
         const std::string& solver, int max_iterations, double tolerance,
         const std::string& fabrik_rotations, int laps, bool warm_start) {
        DrawingOptions options;
        options.solver = solver_kind(solver);
        options.ik.max_iterations = max_iterations;
        options.ik.tolerance = tolerance;
        options.ik.fabrik_rotations = fabrik_rotations_kind(fabrik_rotations);
        options.laps = laps;
        options.warm_start = warm_start;
        check(options.validate());
        std::vector<Vec3> points;
        std::vector<char> flags;
        if (py::isinstance<Trajectory>(targets)) {
          if (!pen_down.is_none()) {
            raise("pen_down must be None when targets is a Trajectory (it has its own)");
          }
          const auto& trajectory = targets.cast<const Trajectory&>();
          points = trajectory.targets;
          flags = trajectory.pen_down;
        } else {
          points = to_vec3s(targets, "targets");
          if (!pen_down.is_none()) flags = pen_flags(pen_down);
        }
        PyDrawingRun out{{}, options, chain.local_offsets()};
        Result<DrawingRun> run = fail("not run");
        {
          py::gil_scoped_release release;
          run = animkit::run_drawing(chain, points, options, flags);
        }
        out.run = unwrap(std::move(run));
        return out;
      },
      py::arg("chain"), py::arg("targets"), py::arg("pen_down") = py::none(),
      py::arg("solver") = std::string(to_string(defaults.solver)),
      py::arg("max_iterations") = ik_defaults.max_iterations,
      py::arg("tolerance") = ik_defaults.tolerance,
      py::arg("fabrik_rotations") = std::string(to_string(ik_defaults.fabrik_rotations)),
      py::arg("laps") = defaults.laps, py::arg("warm_start") = defaults.warm_start,
      "Runs a drawing session as the lab's app and `animkit ik` do: one solve per target, each\n"
      "frame starting from the previous frame's pose (warm_start) or from rest, the arm back\n"
      "at rest when a lap starts. Returns a DrawingRun.\n\n"
      "targets: (n, 3) world points, or a Trajectory (then pen_down comes from it). pen_down:\n"
      "None (all down) or n flags, recorded in the frames. The GIL is released while it runs.\n"
      "Raises animkit.Error for an empty or NaN/inf target list (naming the index), a pen\n"
      "list of another size, laps < 1, bad solver options, more than 10 million frames.");
}

}  // namespace

void bind_kinematics(py::module_& m) {
  bind_chain(m);
  bind_pose(m);
  bind_solve(m);
  bind_drawing_run(m);
}

}  // namespace animkit::python
