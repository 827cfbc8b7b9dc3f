#include "animkit/cloth/integrator_registry.h"

#include <array>
#include <cmath>
#include <string>
#include <type_traits>

#include "animkit/cloth/explicit_euler.h"
#include "animkit/cloth/implicit_euler.h"
#include "animkit/cloth/integrator.h"
#include "animkit/cloth/local_global.h"
#include "animkit/cloth/parameter_ranges.h"
#include "animkit/cloth/vertex_block_descent.h"
#include "animkit/core/validation.h"

namespace animkit {

namespace {

NewtonSettings newton(LinearSolverKind solver) {
  NewtonSettings settings;
  settings.linear_solver = solver;
  return settings;
}

const std::array kEntries{
    IntegratorEntry{
        "implicit-pcg",
        "implicit Euler, Newton + block-Jacobi PCG (the lab's method, fast on soft cloth)",
        newton(LinearSolverKind::pcg), 1, true},
    IntegratorEntry{"implicit-multigrid",
                    "implicit Euler, Newton + smoothed aggregation multigrid PCG (stiff cloth)",
                    newton(LinearSolverKind::multigrid), 1, true},
    IntegratorEntry{"implicit-direct", "implicit Euler, Newton + sparse LDL^T",
                    newton(LinearSolverKind::direct), 1, true},
    IntegratorEntry{"vbd",
                    "implicit Euler, Vertex Block Descent (coloured per-vertex Newton sweeps)",
                    VbdSettings{}},
    IntegratorEntry{"local-global",
                    "implicit Euler, local/global (Liu et al. 2013) + Chebyshev (Wang 2015)",
                    LocalGlobalSettings{}},
    IntegratorEntry{"explicit", "explicit Euler (the lab's 1000 substeps per step)",
                    ExplicitEulerSettings{}, 1000},
};

// Whether two settings select the same integrator (not whether all their values agree).
bool same_integrator(const IntegratorSettings& a, const IntegratorSettings& b) {
  if (a.index() != b.index()) return false;
  if (const auto* newton_a = std::get_if<NewtonSettings>(&a))
    return newton_a->linear_solver == std::get<NewtonSettings>(b).linear_solver;
  return true;
}

}  // namespace

std::span<const IntegratorEntry> cloth_integrators() {
  return kEntries;
}

const IntegratorEntry* find_integrator(std::string_view name) {
  for (const IntegratorEntry& entry : kEntries) {
    if (entry.name == name) return &entry;
  }
  return nullptr;
}

const IntegratorEntry& integrator_entry(const IntegratorSettings& settings) {
  for (const IntegratorEntry& entry : kEntries) {
    if (same_integrator(entry.defaults, settings)) return entry;
  }
  return kEntries.front();  // unreachable: every alternative has an entry (see the tests)
}

std::string integrator_names() {
  std::string names;
  for (const IntegratorEntry& entry : kEntries)
    names += (names.empty() ? "" : ", ") + std::string(entry.name);
  return names;
}

std::optional<Error> validate(const IntegratorSettings& settings) {
  return std::visit([](const auto& s) { return s.validate(); }, settings);
}

std::optional<double> tolerance_of(const IntegratorSettings& settings) {
  return std::visit(
      [](const auto& s) -> std::optional<double> {
        if constexpr (requires { s.tolerance; }) return s.tolerance;
        return std::nullopt;
      },
      settings);
}

void set_tolerance(IntegratorSettings& settings, double tolerance) {
  std::visit(
      [tolerance](auto& s) {
        if constexpr (requires { s.tolerance; }) s.tolerance = tolerance;
      },
      settings);
}

void set_record_iterations(IntegratorSettings& settings, bool record) {
  std::visit(
      [record](auto& s) {
        if constexpr (requires { s.record_iterations; }) s.record_iterations = record;
      },
      settings);
}

std::unique_ptr<ClothIntegrator> make_integrator(std::shared_ptr<const ClothModel> model,
                                                 const IntegratorSettings& settings) {
  // One case per alternative: a new integrator that is not added here fails to compile.
  struct Maker {
    const std::shared_ptr<const ClothModel>& model;
    std::unique_ptr<ClothIntegrator> operator()(const ExplicitEulerSettings&) const {
      return std::make_unique<ExplicitEuler>(model);
    }
    std::unique_ptr<ClothIntegrator> operator()(const NewtonSettings& s) const {
      return std::make_unique<ImplicitEuler>(model, s);
    }
    std::unique_ptr<ClothIntegrator> operator()(const VbdSettings& s) const {
      return std::make_unique<VertexBlockDescent>(model, s);
    }
    std::unique_ptr<ClothIntegrator> operator()(const LocalGlobalSettings& s) const {
      return std::make_unique<LocalGlobal>(model, s);
    }
  };
  return std::visit(Maker{model}, settings);
}

}  // namespace animkit
