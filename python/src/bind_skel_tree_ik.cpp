// IK on skeleton trees from Python (kinematics/tree_ik.h, tree_ik_solver.h): effectors, a
// solver object that holds its settings and workspaces (so repeated solves on one skeleton
// allocate nothing in the library), and a one-call solve_tree.
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <variant>

#include "animkit/kinematics/tree_ik_solver.h"
#include "animkit/kinematics/two_bone_ik.h"
#include "cloth_convert.h"
#include "numpy_convert.h"
#include "python_errors.h"
#include "skel_bindings.h"

namespace animkit::python {

namespace {

/// An effector as the user writes it: the joint by index or by name, resolved at solve time.
struct PyEffector {
  std::variant<int, std::string> joint = -1;
  Vec3 position = Vec3::Zero();
  std::optional<Quat> orientation;
  double weight = 1.0;
};

struct PyTreeIkResult {
  TreeIkResult result;
  SkeletonPose pose;
};

/// Optional per-solver settings of TreeIkSolver's constructor (None: the library's default).
struct SolverOptions {
  int max_iterations = FabrikTreeSettings{}.max_iterations;
  double tolerance = FabrikTreeSettings{}.tolerance;
  std::optional<double> angular_tolerance;
  bool finish_with_dls = FabrikTreeSettings{}.finish_with_dls;
  double damping = DlsSettings{}.lambda;
  double max_step_angle = DlsSettings{}.max_step_angle;
  double orientation_weight = DlsSettings{}.orientation_weight;
};

struct PyTreeIkSolver {
  Skeleton skeleton;
  TreeIkSolverKind kind = TreeIkSolverKind::fabrik;
  TreeIkSolvers solvers;
  std::vector<Effector> effectors;  // reused between solves
  std::vector<JointLimit> limits;
  /// Set while a solve runs without the GIL: a second thread's solve on the same object (which
  /// would share the workspaces) is refused instead. Read and written with the GIL held only.
  bool busy = false;
};

std::string solver_names() {
  std::string names;
  for (TreeIkSolverKind kind : all_tree_ik_solvers()) {
    if (!names.empty()) names += ", ";
    names += to_string(kind);
  }
  return names;
}

TreeIkSolverKind solver_kind(const std::string& name) {
  const auto kind = parse_tree_ik_solver(name);
  if (!kind)
    raise("unknown tree IK solver '" + name + "' (expected one of " + solver_names() + ")");
  return *kind;
}

PyTreeIkSolver make_solver(const Skeleton& skeleton, const std::string& solver,
                           const SolverOptions& o) {
  PyTreeIkSolver s{skeleton, solver_kind(solver), {}, {}, {}, false};
  s.solvers.set_stopping(o.max_iterations, o.tolerance);
  if (o.angular_tolerance) {
    s.solvers.fabrik.angular_tolerance = s.solvers.ccd.angular_tolerance =
        s.solvers.dls.angular_tolerance = *o.angular_tolerance;
  }
  s.solvers.fabrik.finish_with_dls = o.finish_with_dls;
  for (DlsSettings* dls : {&s.solvers.dls, &s.solvers.fabrik.dls_finish}) {
    dls->lambda = o.damping;
    dls->max_step_angle = o.max_step_angle;
    dls->orientation_weight = o.orientation_weight;
  }
  s.solvers.dls.method =
      s.kind == TreeIkSolverKind::sdls ? DlsMethod::selective : DlsMethod::damped;
  check(s.solvers.fabrik.validate());
  check(s.solvers.ccd.validate());
  check(s.solvers.dls.validate());
  return s;
}

PyTreeIkResult solve(PyTreeIkSolver& s, const SkeletonPose* pose, const py::object& effectors,
                     const py::object& limits) {
  if (s.busy) {
    raise(
        "this TreeIkSolver is already solving in another thread (its workspaces are not "
        "shared): give each thread its own solver");
  }
  s.busy = true;
  struct Release {
    bool& busy;
    ~Release() { busy = false; }
  } release_busy{s.busy};
  s.effectors.clear();
  auto add = [&](const py::object& item, std::size_t i) {
    if (!py::isinstance<PyEffector>(item)) {
      raise("effectors[" + std::to_string(i) + "] must be an Effector, got " +
            std::string(py::str(py::type::of(item).attr("__name__"))));
    }
    const auto& e = item.cast<const PyEffector&>();
    Effector out;
    out.joint = joint_index(s.skeleton, py::cast(e.joint), "effector joint");
    out.position = e.position;
    out.orientation = e.orientation;
    out.weight = e.weight;
    s.effectors.push_back(out);
  };
  if (py::isinstance<PyEffector>(effectors)) {
    add(effectors, 0);
  } else if (py::isinstance<py::sequence>(effectors) && !py::isinstance<py::str>(effectors)) {
    const auto list = py::reinterpret_borrow<py::sequence>(effectors);
    for (std::size_t i = 0; i < list.size(); ++i) add(list[i], i);
  } else {
    raise("effectors must be an Effector or a list of them");
  }
  s.limits = to_joint_limits(limits, s.skeleton);
  PyTreeIkResult out;
  out.pose = pose ? *pose : skeleton_rest_pose(s.skeleton);
  Result<TreeIkResult> result;
  {
    py::gil_scoped_release release;
    const TreeIkProblem problem{s.effectors, s.limits};
    result = solve_tree_ik(s.kind, s.skeleton, problem, s.solvers, out.pose);
  }
  out.result = unwrap(std::move(result));
  return out;
}

#define SOLVER_OPTION_ARGS                                                                     \
  py::arg("max_iterations") = SolverOptions{}.max_iterations,                                  \
  py::arg("tolerance") = SolverOptions{}.tolerance, py::arg("angular_tolerance") = py::none(), \
  py::arg("finish_with_dls") = SolverOptions{}.finish_with_dls,                                \
  py::arg("damping") = SolverOptions{}.damping,                                                \
  py::arg("max_step_angle") = SolverOptions{}.max_step_angle,                                  \
  py::arg("orientation_weight") = SolverOptions{}.orientation_weight

SolverOptions options(int max_iterations, double tolerance, std::optional<double> angular,
                      bool finish, double damping, double step, double orientation_weight) {
  return SolverOptions{max_iterations, tolerance, angular,           finish,
                       damping,        step,      orientation_weight};
}

}  // namespace

void bind_skel_tree_ik(py::module_& m) {
  py::class_<PyEffector>(m, "Effector",
                         "An IK end effector: a joint (index or name) and where it should be "
                         "(world, scene units), optionally with an orientation and a weight.")
      .def(py::init([](std::variant<int, std::string> joint, const py::object& position,
                       const py::object& orientation, double weight) {
             PyEffector e;
             e.joint = std::move(joint);
             e.position = to_vec3(position, "effector position");
             if (!orientation.is_none()) e.orientation = to_quat(orientation, "orientation");
             e.weight = weight;
             return e;
           }),
           py::arg("joint"), py::arg("position"), py::arg("orientation") = py::none(),
           py::arg("weight") = Effector{}.weight,
           "joint: index or name (not a root); position (3,) world target; orientation: "
           "(w, x, y, z) unit world orientation or None; weight > 0. Checked at solve time "
           "(animkit.Error naming the problem).")
      .def_readwrite("joint", &PyEffector::joint, "The joint, an index or a name.")
      .def_property(
          "position", [](const PyEffector& e) { return vec3_to_array(e.position); },
          [](PyEffector& e, const py::object& v) { e.position = to_vec3(v, "effector position"); },
          "(3,) target position, world space.")
      .def_property(
          "orientation",
          [](const PyEffector& e) -> py::object {
            if (!e.orientation) return py::none();
            return quat_to_array(*e.orientation);
          },
          [](PyEffector& e, const py::object& v) {
            if (v.is_none()) {
              e.orientation.reset();
            } else {
              e.orientation = to_quat(v, "orientation");
            }
          },
          "(4,) target orientation (w, x, y, z), or None for position only.")
      .def_readwrite("weight", &PyEffector::weight, "Relative importance (> 0).")
      .def("__repr__", [](const PyEffector& e) {
        const std::string joint = std::holds_alternative<int>(e.joint)
                                      ? std::to_string(std::get<int>(e.joint))
                                      : "'" + std::get<std::string>(e.joint) + "'";
        const Vec3& p = e.position;
        std::string text = "Effector(joint=" + joint + ", position=(" + repr_number(p.x()) + ", " +
                           repr_number(p.y()) + ", " + repr_number(p.z()) + "), orientation=";
        if (e.orientation) {
          const Quat& q = *e.orientation;
          text += "(" + repr_number(q.w()) + ", " + repr_number(q.x()) + ", " + repr_number(q.y()) +
                  ", " + repr_number(q.z()) + ")";
        } else {
          text += "None";
        }
        return text + ", weight=" + repr_number(e.weight) + ")";
      });

  py::class_<PyTreeIkResult>(m, "TreeIkResult", "What a tree IK solve did, and its pose.")
      .def_readonly("pose", &PyTreeIkResult::pose, "The solved SkeletonPose (FK run).")
      .def_property_readonly(
          "iterations", [](const PyTreeIkResult& r) { return r.result.iterations; },
          "Full iterations run (sweeps, FABRIK passes or DLS steps).")
      .def_property_readonly(
          "finish_iterations", [](const PyTreeIkResult& r) { return r.result.finish_iterations; },
          "DLS iterations FABRIK's finish ran after its passes.")
      .def_property_readonly(
          "error", [](const PyTreeIkResult& r) { return r.result.error; },
          "Largest effector position error (scene units).")
      .def_property_readonly(
          "orientation_error", [](const PyTreeIkResult& r) { return r.result.orientation_error; },
          "Largest effector orientation error (radians; 0 when none has a target).")
      .def_property_readonly(
          "converged", [](const PyTreeIkResult& r) { return r.result.converged; },
          "Whether the errors are within the tolerances.")
      .def_property_readonly(
          "reachable", [](const PyTreeIkResult& r) { return r.result.reachable; },
          "False when some target is farther than its bones reach.")
      .def("__repr__", [](const PyTreeIkResult& r) {
        return "TreeIkResult(iterations=" + std::to_string(r.result.iterations) +
               ", finish_iterations=" + std::to_string(r.result.finish_iterations) +
               ", error=" + repr_number(r.result.error) +
               ", orientation_error=" + repr_number(r.result.orientation_error) +
               ", converged=" + (r.result.converged ? "True" : "False") +
               ", reachable=" + (r.result.reachable ? "True" : "False") + ")";
      });

  py::class_<PyTreeIkSolver>(m, "TreeIkSolver",
                             "An IK solver for one skeleton tree (fabrik, ccd, dls or sdls) "
                             "holding its settings and workspaces for repeated solves.")
      .def(py::init([](const Skeleton& skeleton, const std::string& solver, int max_iterations,
                       double tolerance, std::optional<double> angular, bool finish, double damping,
                       double step, double orientation_weight) {
             return make_solver(skeleton, solver,
                                options(max_iterations, tolerance, angular, finish, damping, step,
                                        orientation_weight));
           }),
           py::arg("skeleton"), py::arg("solver") = "fabrik", py::kw_only(), SOLVER_OPTION_ARGS,
           "A solver: `solver` one of tree_ik_solver_names(); max_iterations (>= 1) and "
           "tolerance (scene units, > 0) for every solver; angular_tolerance (radians; None: "
           "each solver's default); finish_with_dls (FABRIK continues with DLS when stuck); "
           "damping (DLS lambda, scene units), max_step_angle (radians per iteration) and "
           "orientation_weight (scene units per radian) for DLS, SDLS and FABRIK's finish. "
           "Raises animkit.Error for an unknown solver or an invalid setting.")
      .def_property_readonly(
          "solver", [](const PyTreeIkSolver& s) { return std::string(to_string(s.kind)); },
          "The solver's name.")
      .def_property_readonly(
          "skeleton", [](const PyTreeIkSolver& s) { return s.skeleton; }, "The skeleton.")
      .def_property_readonly(
          "max_iterations", [](const PyTreeIkSolver& s) { return s.solvers.ccd.max_iterations; },
          "Iteration cap.")
      .def_property_readonly(
          "tolerance", [](const PyTreeIkSolver& s) { return s.solvers.ccd.tolerance; },
          "Position tolerance (scene units).")
      .def(
          "solve",
          [](PyTreeIkSolver& s, const py::object& effectors, const SkeletonPose* pose,
             const py::object& limits) { return solve(s, pose, effectors, limits); },
          py::arg("effectors"), py::arg("pose") = nullptr, py::arg("limits") = py::none(),
          "Solves for the effectors (an Effector or a list) from `pose` (None: the rest "
          "pose), with `limits` (one per joint, None: all free) enforced; returns a "
          "TreeIkResult with the new pose (the given one is untouched). Runs without the GIL; "
          "one solver solves in one thread at a time (a second thread's solve raises "
          "animkit.Error). Raises animkit.Error for invalid effectors, limits or a pose of "
          "another size.")
      .def("__repr__", [](const PyTreeIkSolver& s) {
        return "TreeIkSolver(solver='" + std::string(to_string(s.kind)) +
               "', joint_count=" + std::to_string(s.skeleton.joint_count()) +
               ", max_iterations=" + std::to_string(s.solvers.ccd.max_iterations) +
               ", tolerance=" + repr_number(s.solvers.ccd.tolerance) + ")";
      });

  m.def(
      "solve_tree",
      [](const Skeleton& skeleton, const py::object& effectors, const SkeletonPose* pose,
         const std::string& solver, const py::object& limits, int max_iterations, double tolerance,
         std::optional<double> angular, bool finish, double damping, double step,
         double orientation_weight) {
        PyTreeIkSolver s = make_solver(
            skeleton, solver,
            options(max_iterations, tolerance, angular, finish, damping, step, orientation_weight));
        return solve(s, pose, effectors, limits);
      },
      py::arg("skeleton"), py::arg("effectors"), py::arg("pose") = nullptr,
      py::arg("solver") = "fabrik", py::arg("limits") = py::none(), py::kw_only(),
      SOLVER_OPTION_ARGS,
      "One tree IK solve: TreeIkSolver(skeleton, solver, ...).solve(effectors, pose, limits).");
  py::class_<TwoBoneResult>(m, "TwoBoneResult",
                            "What solve_two_bone found: the two world rotations to apply and "
                            "where the middle and end joints go.")
      .def_property_readonly(
          "upper_rotation", [](const TwoBoneResult& r) { return quat_to_array(r.upper_rotation); },
          "(4,) world rotation of the upper bone about the root (w, x, y, z).")
      .def_property_readonly(
          "lower_rotation", [](const TwoBoneResult& r) { return quat_to_array(r.lower_rotation); },
          "(4,) world rotation taking the old lower bone to the new one (w, x, y, z).")
      .def_property_readonly(
          "middle", [](const TwoBoneResult& r) { return vec3_to_array(r.middle); },
          "(3,) new world position of the middle joint.")
      .def_property_readonly(
          "end", [](const TwoBoneResult& r) { return vec3_to_array(r.end); },
          "(3,) new world position of the end joint.")
      .def_readonly("reached", &TwoBoneResult::reached, "Whether the end reaches the target.")
      .def_readonly("error", &TwoBoneResult::error, "|end - target| (scene units).")
      .def("__repr__", [](const TwoBoneResult& r) {
        return std::string("TwoBoneResult(reached=") + (r.reached ? "True" : "False") +
               ", error=" + repr_number(r.error) + ")";
      });

  m.def(
      "solve_two_bone",
      [](const py::object& root, const py::object& middle, const py::object& end,
         const py::object& target, const py::object& pole, double degenerate_length) {
        TwoBoneInput input;
        input.root = to_vec3(root, "root");
        input.middle = to_vec3(middle, "middle");
        input.end = to_vec3(end, "end");
        input.target = to_vec3(target, "target");
        input.pole = to_vec3(pole, "pole");
        TwoBoneSettings settings;
        settings.degenerate_length = degenerate_length;
        return unwrap(solve_two_bone(input, settings));
      },
      py::arg("root"), py::arg("middle"), py::arg("end"), py::arg("target"), py::arg("pole"),
      py::arg("degenerate_length") = TwoBoneSettings{}.degenerate_length,
      "The analytic two-bone solver (hip-knee-ankle, shoulder-elbow-wrist): world positions "
      "of the limb's three joints, the target for the end and a pole the middle joint bends "
      "toward (scene units). Raises animkit.Error naming the problem for degenerate bones, "
      "non-finite input or a bad degenerate_length.");
  m.def(
      "tree_ik_solver_names",
      [] {
        std::vector<std::string> names;
        for (TreeIkSolverKind kind : all_tree_ik_solvers()) names.emplace_back(to_string(kind));
        return names;
      },
      "The tree IK solvers' names, in menu order.");
}

}  // namespace animkit::python
