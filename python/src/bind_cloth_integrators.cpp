// Bindings of the integrators' settings (Newton, VBD, local/global, explicit Euler) and the
// registry's names.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <sstream>
#include <string>
#include <variant>

#include "animkit/cloth/integrator_registry.h"
#include "cloth_convert.h"
#include "numpy_convert.h"
#include "python_errors.h"

namespace animkit::python {
namespace {

constexpr Named<LinearSolverKind> kSolvers[] = {{"direct", LinearSolverKind::direct},
                                                {"pcg", LinearSolverKind::pcg},
                                                {"multigrid", LinearSolverKind::multigrid}};

// The library's names (kHessianProjectionNames); animkit.Error for another.
HessianProjection projection_from(const std::string& name) {
  if (const auto projection = enum_named<HessianProjection>(kHessianProjectionNames, name))
    return *projection;
  raise("unknown Hessian projection '" + name +
        "' (expected one of: " + joined_names(kHessianProjectionNames) + ")");
}

std::string projection_name(HessianProjection projection) {
  return std::string(animkit::enum_name(kHessianProjectionNames, projection));
}

std::string repr_newton(const NewtonSettings& s) {
  return "NewtonSettings(linear_solver='" + enum_name(s.linear_solver, kSolvers) +
         "', tolerance=" + repr_number(s.tolerance) +
         ", max_iterations=" + std::to_string(s.max_iterations) + ", beta=" + repr_number(s.beta) +
         ", gamma=" + repr_number(s.gamma) +
         ", max_line_search_steps=" + std::to_string(s.max_line_search_steps) + ", projection='" +
         projection_name(s.projection) +
         "', record_iterations=" + (s.record_iterations ? "True" : "False") +
         ", velocity_tolerance=" + repr_number(s.velocity_tolerance) +
         ", linear_forcing=" + repr_number(s.linear_forcing) + ")";
}

std::string repr_vbd(const VbdSettings& s) {
  return "VbdSettings(tolerance=" + repr_number(s.tolerance) +
         ", max_iterations=" + std::to_string(s.max_iterations) +
         ", record_iterations=" + (s.record_iterations ? "True" : "False") +
         ", check_interval=" + std::to_string(s.check_interval) +
         ", chebyshev_rho=" + repr_number(s.chebyshev_rho) + ", gamma=" + repr_number(s.gamma) +
         ", max_backtracks=" + std::to_string(s.max_backtracks) + ")";
}

std::string repr_local_global(const LocalGlobalSettings& s) {
  return "LocalGlobalSettings(tolerance=" + repr_number(s.tolerance) +
         ", max_iterations=" + std::to_string(s.max_iterations) +
         ", chebyshev=" + (s.chebyshev ? "True" : "False") +
         ", spectral_radius=" + repr_number(s.spectral_radius) +
         ", chebyshev_delay=" + std::to_string(s.chebyshev_delay) +
         ", monotone=" + (s.monotone ? "True" : "False") +
         ", record_iterations=" + (s.record_iterations ? "True" : "False") + ")";
}

std::string integrator_list() {
  std::string names;
  for (const IntegratorEntry& entry : cloth_integrators())
    names += (names.empty() ? "" : ", ") + std::string(entry.name);
  return names;
}

}  // namespace

std::string repr_integrator(const IntegratorSettings& settings) {
  return std::visit(
      [](const auto& s) -> std::string {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, NewtonSettings>) return repr_newton(s);
        if constexpr (std::is_same_v<S, VbdSettings>) return repr_vbd(s);
        if constexpr (std::is_same_v<S, LocalGlobalSettings>) return repr_local_global(s);
        return "ExplicitEulerSettings()";
      },
      settings);
}

// An integrator given as settings or as the registry's name ("implicit-multigrid").
IntegratorSettings to_integrator(const py::handle& value) {
  if (py::isinstance<py::str>(value)) {
    const std::string name = value.cast<std::string>();
    const IntegratorEntry* entry = find_integrator(name);
    if (!entry)
      raise("unknown integrator '" + name + "' (expected one of: " + integrator_list() + ")");
    return entry->defaults;
  }
  if (py::isinstance<NewtonSettings>(value)) return value.cast<NewtonSettings>();
  if (py::isinstance<VbdSettings>(value)) return value.cast<VbdSettings>();
  if (py::isinstance<LocalGlobalSettings>(value)) return value.cast<LocalGlobalSettings>();
  if (py::isinstance<ExplicitEulerSettings>(value)) return value.cast<ExplicitEulerSettings>();
  throw py::type_error(
      "integrator must be NewtonSettings, VbdSettings, LocalGlobalSettings, "
      "ExplicitEulerSettings or an integrator's name");
}

py::object integrator_object(const IntegratorSettings& settings) {
  return std::visit([](const auto& s) { return py::cast(s); }, settings);
}

void bind_integrators(py::module_& m) {
  const NewtonSettings newton;
  py::class_<NewtonSettings>(
      m, "NewtonSettings",
      "Implicit Euler by Newton's method with a backtracking line search (the lab's "
      "integrator). Stops when |grad g| <= tolerance * |grad g| at the prediction.")
      .def(py::init([](const std::string& linear_solver, double tolerance, int max_iterations,
                       double beta, double gamma, int max_line_search_steps,
                       const std::string& projection, bool record_iterations,
                       double velocity_tolerance, double linear_forcing) {
             NewtonSettings s{parse_enum(linear_solver, kSolvers, "linear solver"),
                              tolerance,
                              max_iterations,
                              beta,
                              gamma,
                              max_line_search_steps,
                              projection_from(projection),
                              record_iterations,
                              velocity_tolerance,
                              linear_forcing};
             check(s.validate());
             return s;
           }),
           "linear_solver: 'direct', 'pcg' or 'multigrid'; projection: 'when_indefinite', "
           "'always' or 'with_terms'. Raises animkit.Error for an unknown name or an "
           "out-of-range value.",
           py::arg("linear_solver") = enum_name(newton.linear_solver, kSolvers),
           py::arg("tolerance") = newton.tolerance,
           py::arg("max_iterations") = newton.max_iterations, py::arg("beta") = newton.beta,
           py::arg("gamma") = newton.gamma,
           py::arg("max_line_search_steps") = newton.max_line_search_steps,
           py::arg("projection") = projection_name(newton.projection),
           py::arg("record_iterations") = newton.record_iterations,
           py::arg("velocity_tolerance") = newton.velocity_tolerance,
           py::arg("linear_forcing") = newton.linear_forcing)
      .def_property(
          "linear_solver",
          [](const NewtonSettings& s) { return enum_name(s.linear_solver, kSolvers); },
          [](NewtonSettings& s, const std::string& v) {
            s.linear_solver = parse_enum(v, kSolvers, "linear solver");
          },
          "'direct', 'pcg' or 'multigrid'.")
      .def_readwrite("tolerance", &NewtonSettings::tolerance,
                     "Relative gradient tolerance, (0, 1).")
      .def_readwrite("max_iterations", &NewtonSettings::max_iterations,
                     "Newton iterations per substep, >= 1.")
      .def_readwrite("beta", &NewtonSettings::beta, "Line-search shrink factor, (0, 1).")
      .def_readwrite("gamma", &NewtonSettings::gamma, "Armijo constant, (0, 1).")
      .def_readwrite("max_line_search_steps", &NewtonSettings::max_line_search_steps,
                     "Backtracking reductions before giving up, >= 1.")
      .def_property(
          "projection",
          [](const NewtonSettings& s) { return projection_name(s.projection); },
          [](NewtonSettings& s, const std::string& v) {
            s.projection = projection_from(v);
          },
          "'when_indefinite' (the exact Hessian first, projected where it meets negative "
          "curvature), 'always' (projected) or 'with_terms' (projected while energy terms "
          "such as contact or wind join the step: the fast settings' choice).")
      .def_readwrite("record_iterations", &NewtonSettings::record_iterations,
                     "Fill StepReport.iterations.")
      .def_readwrite("velocity_tolerance", &NewtonSettings::velocity_tolerance,
                     "IPC's stopping test: a substep also ends when the Newton direction moves "
                     "no particle faster than this fraction of the cloth's bounding-box diagonal "
                     "per second (|dx|_inf / h). 0: off; else [0, 1).")
      .def_readwrite("linear_forcing", &NewtonSettings::linear_forcing,
                     "The relative residual CG solves each Newton system to, [0, 1); 0: "
                     "adaptive (1% of the relative gradient).")
      .def("__repr__", &repr_newton);

  const VbdSettings vbd;
  py::class_<VbdSettings>(m, "VbdSettings",
                          "Vertex Block Descent: coloured Gauss-Seidel sweeps of per-vertex "
                          "Newton steps on the same incremental potential.")
      .def(py::init([](double tolerance, int max_iterations, bool record_iterations,
                       int check_interval, double chebyshev_rho, double gamma, int max_backtracks) {
             VbdSettings s{tolerance,     max_iterations, record_iterations, check_interval,
                           chebyshev_rho, gamma,          max_backtracks};
             check(s.validate());
             return s;
           }),
           "Raises animkit.Error for an out-of-range value.", py::arg("tolerance") = vbd.tolerance,
           py::arg("max_iterations") = vbd.max_iterations,
           py::arg("record_iterations") = vbd.record_iterations,
           py::arg("check_interval") = vbd.check_interval,
           py::arg("chebyshev_rho") = vbd.chebyshev_rho, py::arg("gamma") = vbd.gamma,
           py::arg("max_backtracks") = vbd.max_backtracks)
      .def_readwrite("tolerance", &VbdSettings::tolerance, "Relative gradient tolerance, (0, 1).")
      .def_readwrite("max_iterations", &VbdSettings::max_iterations, "Sweeps per substep, >= 1.")
      .def_readwrite("record_iterations", &VbdSettings::record_iterations,
                     "Fill StepReport.iterations.")
      .def_readwrite("check_interval", &VbdSettings::check_interval,
                     "Sweeps between stopping tests, >= 1.")
      .def_readwrite("chebyshev_rho", &VbdSettings::chebyshev_rho,
                     "Chebyshev spectral radius estimate, [0, 1); 0: off.")
      .def_readwrite("gamma", &VbdSettings::gamma, "Local Armijo constant, (0, 1).")
      .def_readwrite("max_backtracks", &VbdSettings::max_backtracks,
                     "Halvings of a vertex's step, >= 0.")
      .def("__repr__", &repr_vbd);

  const LocalGlobalSettings lg;
  py::class_<LocalGlobalSettings>(
      m, "LocalGlobalSettings",
      "Implicit Euler by the local/global method (Liu et al. 2013), optionally Chebyshev "
      "accelerated.")
      .def(py::init([](double tolerance, int max_iterations, bool chebyshev, double spectral_radius,
                       int chebyshev_delay, bool monotone, bool record_iterations) {
             LocalGlobalSettings s{tolerance,        max_iterations,  chebyshev,
                                   spectral_radius,  chebyshev_delay, monotone,
                                   record_iterations};
             check(s.validate());
             return s;
           }),
           "Raises animkit.Error for an out-of-range value.", py::arg("tolerance") = lg.tolerance,
           py::arg("max_iterations") = lg.max_iterations, py::arg("chebyshev") = lg.chebyshev,
           py::arg("spectral_radius") = lg.spectral_radius,
           py::arg("chebyshev_delay") = lg.chebyshev_delay, py::arg("monotone") = lg.monotone,
           py::arg("record_iterations") = lg.record_iterations)
      .def_readwrite("tolerance", &LocalGlobalSettings::tolerance,
                     "Relative gradient tolerance, (0, 1).")
      .def_readwrite("max_iterations", &LocalGlobalSettings::max_iterations,
                     "Iterations per substep, >= 1.")
      .def_readwrite("chebyshev", &LocalGlobalSettings::chebyshev, "Chebyshev acceleration.")
      .def_readwrite("spectral_radius", &LocalGlobalSettings::spectral_radius,
                     "Spectral radius estimate, (0, 1).")
      .def_readwrite("chebyshev_delay", &LocalGlobalSettings::chebyshev_delay,
                     "Plain iterations before the acceleration, >= 0.")
      .def_readwrite("monotone", &LocalGlobalSettings::monotone,
                     "Reject accelerated iterates that do not decrease g.")
      .def_readwrite("record_iterations", &LocalGlobalSettings::record_iterations,
                     "Fill StepReport.iterations.")
      .def("__repr__", &repr_local_global);

  py::class_<ExplicitEulerSettings>(
      m, "ExplicitEulerSettings",
      "Explicit (symplectic) Euler, the lab's starting point: no settings of its own; its "
      "substeps (ClothScene.substeps, 0 = 1000) keep it stable.")
      .def(py::init<>(), "No settings.")
      .def("__repr__", [](const ExplicitEulerSettings&) { return "ExplicitEulerSettings()"; });

  m.def(
      "integrator_names",
      [] {
        std::vector<std::string> names;
        for (const IntegratorEntry& entry : cloth_integrators()) names.emplace_back(entry.name);
        return names;
      },
      "The integrators' registry names ('implicit-pcg' first, the default), as the CLI's "
      "--integrator takes them.");
  m.def(
      "integrator_settings",
      [](const std::string& name) { return integrator_object(to_integrator(py::str(name))); },
      "The default settings of the integrator called `name` (see integrator_names()). Raises "
      "animkit.Error for an unknown name.",
      py::arg("name"));
}

}  // namespace animkit::python
