// Bindings of the cloth simulator: ClothSimulator (a built ClothWorld), its step reports, and
// the state shared with numpy as read-only views of the simulator's own memory.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "animkit/cloth/cloth_run.h"
#include "animkit/cloth/cloth_world.h"
#include "animkit/cloth/integrator_choice.h"
#include "animkit/cloth/integrator_registry.h"
#include "bindings.h"
#include "cloth_convert.h"
#include "cloth_simulator_object.h"
#include "numpy_convert.h"
#include "python_errors.h"

namespace animkit::python {
namespace {

struct ColliderPose {
  std::string name;
  Vec3 position;
  Quat rotation;
};

std::string yes_no(bool value) {
  return value ? "True" : "False";
}

std::string repr_record(const IterationRecord& r) {
  return "IterationRecord(gradient_norm=" + repr_number(r.gradient_norm) +
         ", ms=" + repr_number(r.ms) + ", objective=" + repr_number(r.objective) +
         ", objective_after=" + repr_number(r.objective_after) +
         ", decrease=" + repr_number(r.decrease) + ", slope=" + repr_number(r.slope) +
         ", alpha=" + repr_number(r.alpha) +
         ", line_search_steps=" + std::to_string(r.line_search_steps) +
         ", linear_iterations=" + std::to_string(r.linear_iterations) +
         ", projected=" + yes_no(r.projected) + ")";
}

std::string repr_report(const StepReport& r) {
  std::string text = "StepReport(substeps=" + std::to_string(r.substeps) +
                     ", newton_iterations=" + std::to_string(r.newton_iterations) +
                     ", line_search_steps=" + std::to_string(r.line_search_steps) +
                     ", linear_iterations=" + std::to_string(r.linear_iterations) +
                     ", projected_iterations=" + std::to_string(r.projected_iterations) +
                     ", gradient_norm_start=" + repr_number(r.gradient_norm_start) +
                     ", gradient_norm_end=" + repr_number(r.gradient_norm_end) +
                     ", gradient_tolerance=" + repr_number(r.gradient_tolerance) +
                     ", newton_speed_end=" + repr_number(r.newton_speed_end) +
                     ", converged=" + yes_no(r.converged) + ", energy=" + repr_number(r.energy) +
                     ", ms=" + repr_number(r.ms) +
                     ", friction_iterations=" + std::to_string(r.friction_iterations) +
                     ", step_bound_min=" + repr_number(r.step_bound_min);
  if (r.has_contact) {
    text += ", contact_pairs=" + std::to_string(r.contact_pairs) +
            ", min_contact_distance=" + repr_number(r.min_contact_distance);
  }
  return text + ", iterations=<" + std::to_string(r.iterations.size()) + " records>)";
}

// A read-only (n, 3) float64 view of one of the state's vectors, kept alive by `owner`.
py::array state_view(const py::object& owner, const Eigen::VectorXd& v) {
  const py::ssize_t n = v.size() / 3;
  py::array view(py::dtype::of<double>(), {n, py::ssize_t{3}},
                 {py::ssize_t{3 * sizeof(double)}, py::ssize_t{sizeof(double)}}, v.data(), owner);
  py::detail::array_proxy(view.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return view;
}

Eigen::VectorXd flat(const std::vector<Vec3>& points) {
  Eigen::VectorXd out(3 * static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    out.segment<3>(3 * static_cast<Eigen::Index>(i)) = points[i];
  return out;
}

// points as an (n, 3) array with n the cloth's particle count, or animkit.Error.
Eigen::VectorXd particle_vectors(const SimulatorObject& s, const py::handle& value,
                                 std::string_view what) {
  const std::vector<Vec3> points = to_vec3s(value, what);
  const int n = s.sim().model().particle_count();
  if (static_cast<int>(points.size()) != n) {
    raise(std::string(what) + " must have one row per particle (" + std::to_string(n) + "), got " +
          std::to_string(points.size()));
  }
  return flat(points);
}

// A run's Python side, the last of its sinks: after each step it publishes the step (for other
// threads), lets go of the simulator's mutex, and with the GIL calls the Python callables
// (callback(frame, report); False stops the run) and checks for Ctrl-C. A Python exception is
// kept for rethrow() once the run is back under the GIL.
class PythonFrames final : public ClothSink {
 public:
  PythonFrames(SimulatorObject& s, std::unique_lock<std::mutex>& lock,
               std::vector<py::object> callables)
      : s_(s), lock_(lock), callables_(std::move(callables)) {}

  Result<void> begin(const ClothFrame&, int, double) override { return {}; }
  Result<void> frame(const ClothFrame& frame) override {
    s_.publish();
    reports_.push_back(*frame.step);
    lock_.unlock();
    {
      py::gil_scoped_acquire gil;
      try {
        for (const py::object& callable : callables_) {
          const py::object keep_going = callable(frame.frame, reports_.back());
          if (keep_going.is(py::bool_(false))) stopped_ = true;
        }
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      } catch (py::error_already_set& e) {
        error_.emplace(std::move(e));
        stopped_ = true;
      }
    }
    lock_.lock();
    if (stopped_) return fail("stopped");
    return {};
  }
  Result<void> finish(const ClothRun&, const ClothFrame&) override { return {}; }

  bool stopped() const { return stopped_; }
  std::vector<StepReport>& reports() { return reports_; }
  /// Raises the callables' exception (or Ctrl-C's), if one stopped the run. Needs the GIL.
  void rethrow() {
    if (error_) {
      py::error_already_set e = std::move(*error_);
      error_.reset();
      throw e;
    }
  }

 private:
  SimulatorObject& s_;
  std::unique_lock<std::mutex>& lock_;
  std::vector<py::object> callables_;
  std::vector<StepReport> reports_;
  std::optional<py::error_already_set> error_;
  bool stopped_ = false;
};

std::unique_ptr<SimulatorObject> make_simulator(const ClothWorldDesc& scene) {
  auto object = std::make_unique<SimulatorObject>();
  object->desc = scene;
  Result<ClothDesc> cloth = fail("not built");
  Result<ClothWorld> world = fail("not built");
  {
    py::gil_scoped_release release;
    // From the object's own copy: `scene` is Python's, which another thread may change while
    // this one runs without the GIL.
    if (object->desc.choose_integrator) {  // the scene said "auto": measure, then take the winner
      const double tolerance = tolerance_of(object->desc.simulation.integrator).value_or(1e-6);
      const auto choice = choose_integrator(object->desc, tolerance);
      if (choice) {
        object->desc.simulation.integrator = choice->settings;
        object->desc.choose_integrator = false;
      } else {
        cloth = fail(choice.error().message);  // raised below, as a sheet's error would be
      }
    }
    if (!object->desc.choose_integrator) {
      cloth = build_world_cloth(object->desc);
      if (cloth) world = build_cloth_world(object->desc);
    }
  }
  object->cloth = unwrap(std::move(cloth));
  object->world = std::make_unique<ClothWorld>(unwrap(std::move(world)));
  object->initial = object->sim().state();
  object->publish();
  return object;
}

void bind_reports(py::module_& m) {
  py::class_<IterationRecord>(
      m, "IterationRecord",
      "One iteration of an implicit integrator (recorded when its settings' "
      "record_iterations is set). The fields after `ms` are Newton's. Read-only.")
      .def_readonly("gradient_norm", &IterationRecord::gradient_norm,
                    "|grad g| at the iteration's end.")
      .def_readonly("ms", &IterationRecord::ms,
                    "Wall time from the substep's start to this iteration's end, ms.")
      .def_readonly("objective", &IterationRecord::objective, "g(x_k).")
      .def_readonly("objective_after", &IterationRecord::objective_after, "g(x_k + alpha dx).")
      .def_readonly("decrease", &IterationRecord::decrease,
                    "g(x_k + alpha dx) - g(x_k) as the line search computed it.")
      .def_readonly("slope", &IterationRecord::slope, "grad g(x_k) . dx.")
      .def_readonly("alpha", &IterationRecord::alpha, "Accepted step length.")
      .def_readonly("line_search_steps", &IterationRecord::line_search_steps,
                    "Backtracking reductions.")
      .def_readonly("linear_iterations", &IterationRecord::linear_iterations,
                    "PCG iterations of this iteration's solves (0: direct).")
      .def_readonly("projected", &IterationRecord::projected, "Solved with the projected Hessian.")
      .def("__repr__", &repr_record);

  py::class_<StepReport>(m, "StepReport",
                         "What one cloth step did: iterations, convergence, energy, timings "
                         "(ms, wall time) and contact. Read-only.")
      .def_readonly("substeps", &StepReport::substeps, "Substeps of the step.")
      .def_readonly("newton_iterations", &StepReport::newton_iterations,
                    "Implicit solver iterations (Newton, local/global, VBD sweeps), summed over "
                    "substeps (0 for explicit Euler).")
      .def_readonly("line_search_steps", &StepReport::line_search_steps,
                    "Backtracking reductions, summed.")
      .def_readonly("linear_iterations", &StepReport::linear_iterations,
                    "PCG iterations, summed (0 for a direct solve).")
      .def_readonly("projected_iterations", &StepReport::projected_iterations,
                    "Newton iterations that needed the projected Hessian.")
      .def_readonly("gradient_norm_start", &StepReport::gradient_norm_start,
                    "|grad g| at the prediction (first substep).")
      .def_readonly("gradient_norm_end", &StepReport::gradient_norm_end,
                    "|grad g| at the accepted x (last substep).")
      .def_readonly("gradient_tolerance", &StepReport::gradient_tolerance,
                    "The |grad g| the solver stopped at.")
      .def_readonly("newton_speed_end", &StepReport::newton_speed_end,
                    "|dx|_inf / h of the last Newton direction (m/s), what "
                    "NewtonSettings.velocity_tolerance bounds.")
      .def_readonly("speed_tolerance", &StepReport::speed_tolerance,
                    "The newton_speed_end a substep may end at (m/s; 0 when the velocity stop "
                    "is off): a converged step met this or gradient_tolerance.")
      .def_readonly("converged", &StepReport::converged, "Every substep reached its stopping test.")
      .def_readonly("energy", &StepReport::energy, "Total mechanical energy after the step.")
      .def_readonly("ms", &StepReport::ms, "Wall time of the whole step, ms.")
      .def_readonly("friction_iterations", &StepReport::friction_iterations,
                    "Friction's lagged minimizations, summed.")
      .def_readonly("ms_gradient", &StepReport::ms_gradient, "Gradient/objective time, ms.")
      .def_readonly("ms_hessian", &StepReport::ms_hessian, "Hessian assembly time, ms.")
      .def_readonly("ms_linear_solve", &StepReport::ms_linear_solve, "Linear solve time, ms.")
      .def_readonly("ms_line_search", &StepReport::ms_line_search, "Line search time, ms.")
      .def_readonly("ms_term_updates", &StepReport::ms_term_updates,
                    "Energy terms' per-iterate updates, ms.")
      .def_readonly("ms_step_bound", &StepReport::ms_step_bound,
                    "Step bounds (continuous collision detection), ms.")
      .def_readonly("step_bound_min", &StepReport::step_bound_min,
                    "Smallest fraction of a step the energy terms admitted (1: none bounded).")
      .def_readonly("has_contact", &StepReport::has_contact, "The run has contact.")
      .def_readonly("contact_pairs", &StepReport::contact_pairs,
                    "Pairs closer than the contact thickness at the step's end.")
      .def_readonly("min_contact_distance", &StepReport::min_contact_distance,
                    "Smallest distance among them, m.")
      .def_property_readonly(
          "iterations", [](const StepReport& r) { return r.iterations; },
          "The IterationRecord list (empty unless the integrator's record_iterations is set).")
      .def("__repr__", &repr_report);

  py::class_<ClothEnergy>(m, "ClothEnergy",
                          "Energies of a cloth state: kinetic, elastic (springs and bends), "
                          "gravitational and their total. Read-only.")
      .def_readonly("kinetic", &ClothEnergy::kinetic, "1/2 sum m v^2.")
      .def_readonly("elastic", &ClothEnergy::elastic, "Springs' and bends' energy.")
      .def_readonly("gravitational", &ClothEnergy::gravitational, "sum m g y.")
      .def_readonly("total", &ClothEnergy::total, "Their sum.")
      .def("__repr__", [](const ClothEnergy& e) {
        return "ClothEnergy(kinetic=" + repr_number(e.kinetic) +
               ", elastic=" + repr_number(e.elastic) +
               ", gravitational=" + repr_number(e.gravitational) +
               ", total=" + repr_number(e.total) + ")";
      });

  py::class_<ColliderPose>(m, "ColliderPose",
                           "Where a collider is in a simulation now: its name, position (m) "
                           "and rotation (w, x, y, z). Read-only.")
      .def_readonly("name", &ColliderPose::name, "The collider's name.")
      .def_property_readonly(
          "position", [](const ColliderPose& p) { return vec3_to_array(p.position); },
          "Its origin, world space, m.")
      .def_property_readonly(
          "rotation", [](const ColliderPose& p) { return quat_to_array(p.rotation); },
          "Local to world, (w, x, y, z).")
      .def("__repr__", [](const ColliderPose& p) {
        return "ColliderPose(name=" + py::repr(py::str(p.name)).cast<std::string>() +
               ", position=" + repr_vec3(p.position) + ", rotation=" + repr_quat(p.rotation) + ")";
      });
}

}  // namespace

void bind_cloth_simulator(py::module_& m) {
  bind_reports(m);
  py::class_<SimulatorObject>(
      m, "ClothSimulator",
      "A cloth scene being simulated (the library's build_cloth_world: the simulator with its "
      "contact, friction and air terms). step() and run() release the GIL while C++ runs; "
      "positions and velocities are read-only numpy views of the simulator's own state, "
      "updated in place by every step.")
      .def(py::init(&make_simulator),
           "Builds the scene's world (a scene file's \"integrator\": \"auto\" is resolved "
           "here: the integrators run its first 3 steps and the fastest is kept). Raises "
           "animkit.Error naming the first problem (an invalid scene, a cloth starting inside, "
           "touching or through a collider, below the ground, or through itself).",
           py::arg("scene"))
      .def(
          "step",
          [](SimulatorObject& s, std::optional<double> dt) {
            const double h = dt.value_or(s.desc.time_step);
            std::optional<Result<StepReport>> result;
            {
              py::gil_scoped_release release;
              std::lock_guard lock(s.mutex);
              result.emplace(s.sim().step(h));
              s.publish();
            }
            return unwrap(std::move(*result));
          },
          "Advances by dt seconds (None: the scene's dt) and returns the StepReport. Raises "
          "animkit.Error for a dt out of range or a diverging step, which is undone (the state "
          "stays as it was).",
          py::arg("dt") = py::none())
      .def(
          "run",
          [](SimulatorObject& s, std::optional<int> frames, py::object callback,
             const py::iterable& sinks) {
            const int n = frames.value_or(s.desc.frames);
            if (n < 1 || n > kMaxWorldFrames) {
              raise("frames must be between 1 and " + std::to_string(kMaxWorldFrames) + ", got " +
                    std::to_string(n));
            }
            std::vector<py::object> callables;
            if (!callback.is_none()) callables.push_back(callback);
            std::vector<ClothSink*> all;
            // Held for the whole run: `sinks` may be a generator, or a list another thread
            // empties between steps.
            std::vector<py::object> held;
            for (py::handle item : sinks) {
              if (py::isinstance<ClothSink>(item)) {
                held.push_back(py::reinterpret_borrow<py::object>(item));
                ClothSink* sink = item.cast<ClothSink*>();
                if (std::find(all.begin(), all.end(), sink) != all.end()) {
                  raise("the same sink is in sinks twice (each writes its own files once)");
                }
                all.push_back(sink);
              } else if (PyCallable_Check(item.ptr()) != 0) {
                callables.push_back(py::reinterpret_borrow<py::object>(item));
              } else {
                raise(
                    "sinks must be animkit sinks (PointCacheSink, ObjSink, GltfSink) or "
                    "callables, got " +
                    std::string(py::str(item.get_type().attr("__name__"))));
              }
            }
            std::unique_lock lock(s.mutex, std::defer_lock);
            PythonFrames python(s, lock, std::move(callables));
            all.push_back(&python);
            Result<ClothRun> run = fail("not run");
            {
              // Each step without the GIL and with the simulator's mutex; between steps the
              // other way round (PythonFrames).
              py::gil_scoped_release release;
              lock.lock();
              run = run_cloth(*s.world, n, s.desc.time_step, all);
              lock.unlock();
            }
            python.rethrow();
            if (python.stopped()) return python.reports();
            if (!run) raise(run.error());
            if (run->divergence) raise(*run->divergence);
            return std::move(run->steps);
          },
          "Takes `frames` steps of the scene's dt (None: the scene's frames) and returns their "
          "StepReports. callback(frame, report), if given, is called after each step (frame "
          "counts from 1) with the GIL held; returning False stops the run. sinks: outputs "
          "written frame by frame (PointCacheSink, ObjSink, GltfSink; their files are whole "
          "when the run ends without diverging or being stopped, else absent) and more "
          "callables like callback. Each step runs without the GIL. Raises animkit.Error when "
          "a step diverges (that step is undone: the state is the last good one); Ctrl-C "
          "(KeyboardInterrupt) stops it after the current step.",
          py::arg("frames") = py::none(), py::arg("callback") = py::none(),
          py::arg("sinks") = py::tuple())
      .def(
          "energy",
          [](const SimulatorObject& s) {
            py::gil_scoped_release release;  // another thread may hold the mutex a while
            std::lock_guard lock(s.mutex);
            return cloth_energy(s.sim().model(), s.sim().state());
          },
          "The state's ClothEnergy (kinetic, elastic, gravitational, total).")
      .def_property_readonly(
          "positions",
          [](const py::object& self) {
            return state_view(self, self.cast<const SimulatorObject&>().sim().state().positions);
          },
          "Particle positions (n, 3), a read-only view of the simulator's memory: it shows each "
          "step's result without copying (np.array(sim.positions) for a snapshot).")
      .def_property_readonly(
          "velocities",
          [](const py::object& self) {
            return state_view(self, self.cast<const SimulatorObject&>().sim().state().velocities);
          },
          "Particle velocities (n, 3), units/s, a read-only view like positions.")
      .def(
          "set_state",
          [](SimulatorObject& s, py::object positions, py::object velocities,
             std::optional<double> time) {
            ClothState state;
            state.positions = particle_vectors(s, positions, "positions");
            state.velocities = velocities.is_none()
                                   ? Eigen::VectorXd(Eigen::VectorXd::Zero(state.positions.size()))
                                   : particle_vectors(s, velocities, "velocities");
            py::gil_scoped_release release;  // another thread may hold the mutex a while
            std::lock_guard lock(s.mutex);
            state.time = time.value_or(s.sim().state().time);
            Result<void> done = s.sim().set_state(state);
            s.publish();
            unwrap(std::move(done));
          },
          "Replaces the state: positions (n, 3), velocities (n, 3) (None: at rest), time in s "
          "(None: unchanged). Pinned particles get zero velocity. Raises animkit.Error for a "
          "wrong shape or a non-finite value.",
          py::arg("positions"), py::arg("velocities") = py::none(), py::arg("time") = py::none())
      .def(
          "set_external_forces",
          [](SimulatorObject& s, py::object forces) {
            const Eigen::VectorXd f = particle_vectors(s, forces, "forces");
            py::gil_scoped_release release;  // another thread may hold the mutex a while
            std::lock_guard lock(s.mutex);
            unwrap(s.sim().set_external_forces(f));
          },
          "Forces (n, 3) added in every later step, held constant over each step (forces on "
          "pinned particles do nothing). Raises animkit.Error for a wrong shape or a "
          "non-finite value.",
          py::arg("forces"))
      .def(
          "clear_external_forces",
          [](SimulatorObject& s) {
            py::gil_scoped_release release;  // another thread may hold the mutex a while
            std::lock_guard lock(s.mutex);
            s.sim().clear_external_forces();
          },
          "Removes the external forces.")
      .def_property_readonly(
          "particle_count",
          [](const SimulatorObject& s) { return s.sim().model().particle_count(); },
          "Number of particles.")
      .def_property_readonly(
          "triangles",
          [](const SimulatorObject& s) { return triangles_to_array(s.sim().model().triangles); },
          "The surface's triangles (m, 3) int32 particle indices, a copy.")
      .def_property_readonly(
          "springs",
          [](const SimulatorObject& s) {
            const auto& springs = s.sim().model().springs;
            py::array_t<int> out({static_cast<py::ssize_t>(springs.size()), py::ssize_t{2}});
            auto v = out.mutable_unchecked<2>();
            for (std::size_t k = 0; k < springs.size(); ++k) {
              v(static_cast<py::ssize_t>(k), 0) = springs[k][0];
              v(static_cast<py::ssize_t>(k), 1) = springs[k][1];
            }
            return out;
          },
          "The springs' particle pairs (k, 2) int32, a copy.")
      .def_property_readonly(
          "pinned",
          [](const SimulatorObject& s) {
            const auto& pinned = s.sim().model().pinned;
            py::array_t<bool> out(static_cast<py::ssize_t>(pinned.size()));
            auto v = out.mutable_unchecked<1>();
            for (std::size_t i = 0; i < pinned.size(); ++i)
              v(static_cast<py::ssize_t>(i)) = pinned[i] != 0;
            return out;
          },
          "Which particles are pinned, (n,) bool, a copy.")
      .def_property_readonly(
          "masses",
          [](const SimulatorObject& s) {
            const auto& mass = s.sim().model().mass;
            return py::array_t<double>(static_cast<py::ssize_t>(mass.size()), mass.data());
          },
          "Particle masses (n,), a copy.")
      .def_property_readonly(
          "time", [](const SimulatorObject& s) { return s.time.load(); },
          "Simulated time, s. Safe to read from another thread while step() or run() runs "
          "(published after each step, like steps_taken).")
      .def_property_readonly(
          "steps_taken", [](const SimulatorObject& s) { return s.steps_taken.load(); },
          "Steps taken so far (diverged ones not counted). Safe to read from another thread "
          "while step() or run() runs (e.g. for a progress bar): it counts run()'s steps as "
          "they finish.")
      .def_property_readonly(
          "dt", [](const SimulatorObject& s) { return s.desc.time_step; },
          "The scene's seconds per step.")
      .def_property_readonly(
          "integrator_name",
          [](const SimulatorObject& s) {
            return std::string(integrator_entry(s.sim().options().integrator).name);
          },
          "The integrator's registry name.")
      .def_property_readonly(
          "scene", [](const SimulatorObject& s) { return s.desc; },
          "The ClothScene it was built from (a copy).")
      .def_property_readonly(
          "collider_poses",
          [](const SimulatorObject& s) {
            py::gil_scoped_release release;  // another thread may hold the mutex a while
            std::lock_guard lock(s.mutex);
            std::vector<ColliderPose> poses;
            for (const Collider& c : s.posed_colliders())
              poses.push_back({c.name(), c.pose().position, c.pose().rotation});
            return poses;
          },
          "Every collider's pose now (ColliderPose list, scene order): where the solver has "
          "it, on its path or short of it when continuous collision detection held it back.")
      .def(
          "collider_vertices",
          [](const SimulatorObject& s) {
            std::vector<std::vector<Vec3>> vertices;
            {
              py::gil_scoped_release release;
              std::lock_guard lock(s.mutex);
              for (const Collider& c : s.posed_colliders()) vertices.push_back(c.world_vertices());
            }
            py::list out;
            for (const auto& v : vertices) out.append(vec3s_to_array(v));
            return out;
          },
          "Each collider's surface vertices now, world space (a list of (k, 3) arrays, in the "
          "order of the colliders' exported OBJ surfaces).")
      .def("__repr__", [](const SimulatorObject& s) {
        return "ClothSimulator(particles=" + std::to_string(s.sim().model().particle_count()) +
               ", integrator='" + std::string(integrator_entry(s.sim().options().integrator).name) +
               "', time=" + repr_number(s.time.load()) +
               ", steps_taken=" + std::to_string(s.steps_taken.load()) + ")";
      });
}

}  // namespace animkit::python
