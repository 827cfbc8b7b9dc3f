#include "animkit/io/cloth_report.h"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace animkit {

std::string cloth_metrics_json(const ClothRunInfo& info, std::span<const StepReport> steps) {
  const ClothRunSummary s = summarize(steps);
  nlohmann::ordered_json j = {
      {"frames", s.frames},
      {"particles", info.particles},
      {"springs", info.springs},
      {"integrator", info.integrator},
      {"scene", info.scene.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(info.scene)},
      {"diverged", info.divergence.has_value()},
      {"ms_per_step", {{"median", s.ms_per_step_median}, {"mean", s.ms_per_step_mean}}},
      {"newton_iterations", {{"mean", s.newton_iterations_mean}, {"max", s.newton_iterations_max}}},
      {"linear_iterations", {{"mean", s.linear_iterations_mean}}},
      {"line_search_steps", {{"mean", s.line_search_steps_mean}}},
      {"converged_fraction", s.converged_fraction},
      {"final_energy", s.final_energy},
      {"options",
       {{"grid", info.grid},
        {"material",
         info.material.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(info.material)},
        {"size", info.size},
        {"dt", info.dt},
        {"substeps", info.substeps},
        {"mass", info.mass},
        {"stiffness", info.stiffness},
        {"damping", info.damping},
        {"gravity", info.gravity},
        {"tolerance", info.tolerance}}},
  };
  // A material's sheet takes its masses and stiffnesses from the material: the lab's
  // per-particle parameters played no part, so they are not reported as if they had.
  if (!info.material.empty()) {
    for (const char* unused : {"mass", "stiffness", "damping"}) j["options"].erase(unused);
  }
  if (info.divergence) j["divergence"] = *info.divergence;
  if (!steps.empty() && steps.front().has_contact) {
    // The run's closest approach and tightest continuous-collision bound, over every step.
    double closest = steps.front().min_contact_distance, bound = 1.0;
    int most = 0;
    for (const StepReport& r : steps) {
      closest = std::min(closest, r.min_contact_distance);
      bound = std::min(bound, r.step_bound_min);
      most = std::max(most, r.contact_pairs);
    }
    j["contact"] = {{"min_distance", closest}, {"pairs_max", most}, {"step_bound_min", bound}};
  }
  nlohmann::ordered_json per_step = nlohmann::ordered_json::array();
  for (const StepReport& r : steps) {
    nlohmann::ordered_json step = {{"newton_iterations", r.newton_iterations},
                                   {"line_search_steps", r.line_search_steps},
                                   {"linear_iterations", r.linear_iterations},
                                   {"projected_iterations", r.projected_iterations},
                                   {"gradient_norm_start", r.gradient_norm_start},
                                   {"gradient_norm_end", r.gradient_norm_end},
                                   {"gradient_tolerance", r.gradient_tolerance},
                                   {"newton_speed_end", r.newton_speed_end},
                                   {"speed_tolerance", r.speed_tolerance},
                                   {"converged", r.converged},
                                   {"energy", r.energy},
                                   {"ms", r.ms},
                                   {"ms_gradient", r.ms_gradient},
                                   {"ms_hessian", r.ms_hessian},
                                   {"ms_linear_solve", r.ms_linear_solve},
                                   {"ms_line_search", r.ms_line_search},
                                   {"ms_term_updates", r.ms_term_updates},
                                   {"ms_step_bound", r.ms_step_bound},
                                   {"step_bound_min", r.step_bound_min}};
    if (r.has_contact) {
      step["contact_pairs"] = r.contact_pairs;
      step["min_contact_distance"] = r.min_contact_distance;
      step["friction_iterations"] = r.friction_iterations;
    }
    per_step.push_back(std::move(step));
  }
  j["steps"] = std::move(per_step);
  return j.dump(1) + "\n";
}

}  // namespace animkit
