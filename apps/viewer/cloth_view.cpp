#include "cloth_view.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <vector>

#include "animkit/cloth/integrator_registry.h"

namespace animkit::viewer {

namespace {
constexpr double kGrabRadiusPx = 12.0;

// The total energy of the last steps as a line, with its range written in the corners, so a
// user sees damping take energy out (or a bad setting pump it in).
void energy_plot(const std::deque<double>& energy, float height) {
  if (energy.size() < 2) return;
  const auto [lo_it, hi_it] = std::minmax_element(energy.begin(), energy.end());
  const double lo = *lo_it, hi = *hi_it, span = hi > lo ? hi - lo : 1.0;
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x;
  const ImVec2 p1(p0.x + width, p0.y + height);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(p0, p1, ImGui::GetColorU32(ImGuiCol_FrameBg));
  std::vector<ImVec2> points;
  points.reserve(energy.size());
  const float dx = width / static_cast<float>(ClothScene::kEnergyHistory - 1);
  for (std::size_t i = 0; i < energy.size(); ++i) {
    const double t = (energy[i] - lo) / span;
    points.emplace_back(p0.x + dx * static_cast<float>(i),
                        p1.y - 4.0f - static_cast<float>(t) * (height - 8.0f));
  }
  draw->AddPolyline(points.data(), static_cast<int>(points.size()),
                    ImGui::GetColorU32(ImGuiCol_PlotLines), 0, 1.5f);
  char label[64];
  std::snprintf(label, sizeof label, "total energy, max %.4g", hi);
  draw->AddText(ImVec2(p0.x + 4.0f, p0.y + 2.0f), ImGui::GetColorU32(ImGuiCol_Text), label);
  std::snprintf(label, sizeof label, "min %.4g", lo);
  draw->AddText(ImVec2(p0.x + 4.0f, p1.y - ImGui::GetTextLineHeight() - 2.0f),
                ImGui::GetColorU32(ImGuiCol_Text), label);
  ImGui::Dummy(ImVec2(width, height));
}

}  // namespace

ClothView::ClothView(ClothScene scene) : scene_(std::move(scene)), edited_(scene_.options()) {}

Result<ClothView> ClothView::create(const ClothSceneOptions& options) {
  auto scene = ClothScene::create(options);
  if (!scene) return fail(scene.error().message);
  return ClothView(std::move(*scene));
}

void ClothView::step_once() {
  if (auto report = scene_.step(); !report) {
    message_ = report.error().message;
    playing_ = false;
  }
}

void ClothView::advance(double /*seconds*/) {
  // The lab's convention: one step of the chosen time step per displayed frame.
  if (playing_) step_once();
}

void ClothView::apply(const ClothSceneOptions& options) {
  if (auto applied = scene_.apply(options); !applied) {
    message_ = applied.error().message;
    edited_ = scene_.options();
  } else {
    message_.clear();
  }
}

void ClothView::panel() {
  ClothSceneOptions o = edited_;
  GridClothOptions& g = o.grid;
  bool changed = false;
  const auto slider = [&](const char* label, double& value, float lo, float hi, const char* fmt) {
    float v = static_cast<float>(value);
    if (ImGui::SliderFloat(label, &v, lo, hi, fmt)) {
      value = v;
      changed = true;
    }
  };
  slider("Mass", g.mass, 0.5f, 10.0f, "%.2f");
  slider("Stiffness", g.stiffness, 10.0f, 300.0f, "%.0f");
  slider("Damping", g.damping, 0.1f, 10.0f, "%.2f");
  slider("Gravity", g.gravity, 0.1f, 1.0f, "%.2f");
  float step_ms = static_cast<float>(1000.0 * o.time_step);
  if (ImGui::SliderFloat("Time step", &step_ms, 1.0f, 100.0f, "%.1f ms")) {
    o.time_step = step_ms / 1000.0;
    changed = true;
  }
  if (ImGui::SliderInt("Grid cells", &g.cells, 2, 60)) changed = true;
  const IntegratorEntry& current = integrator_entry(o.simulation.integrator);
  if (ImGui::BeginCombo("Integrator", current.name.data())) {
    for (const IntegratorEntry& entry : cloth_integrators()) {
      if (ImGui::Selectable(entry.name.data(), &entry == &current)) {
        o.simulation.integrator = entry.defaults;
        changed = true;
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", entry.summary.data());
    }
    ImGui::EndCombo();
  }
  if (changed) {
    edited_ = o;
    apply(o);
  }
  if (ImGui::Button(playing_ ? "Stop" : "Start")) playing_ = !playing_;
  ImGui::SameLine();
  if (ImGui::Button("Step")) {
    playing_ = false;
    step_once();
  }
  ImGui::SameLine();
  if (ImGui::Button("Reset")) {
    if (auto reset = scene_.reset(edited_); !reset)
      message_ = reset.error().message;
    else
      message_.clear();
  }
  ImGui::Checkbox("Surface", &style_.surface);
  ImGui::SameLine();
  ImGui::Checkbox("Springs", &style_.springs);
  ImGui::SameLine();
  ImGui::Checkbox("Particles", &style_.particles);

  ImGui::Separator();
  const ClothModel& model = scene_.simulator().model();
  ImGui::Text("%d particles, %d springs", model.particle_count(), model.spring_count());
  if (const auto& step = scene_.last_step()) {
    ImGui::Text("Step time   %.3f ms", step->ms);
    ImGui::Text("Newton      %d iterations (%d CG)", step->newton_iterations,
                step->linear_iterations);
    ImGui::Text("Converged   %s", step->converged ? "yes" : "no");
    ImGui::Text("Energy      %.4g", step->energy);
  }
  energy_plot(scene_.energy_history(), 90.0f);
  if (!message_.empty()) ImGui::TextColored(ImVec4(0.9f, 0.2f, 0.2f, 1.0f), "%s", message_.c_str());
  ImGui::Separator();
  ImGui::TextWrapped("Drag a particle to pull it on a spring; click one to pin or unpin it.");
}

bool ClothView::press(const Cursor& cursor) {
  grabbed_ = scene_.pick(*cursor.camera, cursor.x, cursor.y, cursor.view_width, cursor.view_height,
                         kGrabRadiusPx);
  if (!grabbed_) return false;
  grab_plane_point_ = scene_.simulator().state().position(*grabbed_);
  return true;
}

void ClothView::drag(const Cursor& cursor) {
  if (!grabbed_) return;
  // The particle moves in the plane through where it was grabbed, facing the camera.
  const Vec3 facing = cursor.camera->eye() - cursor.camera->focus;
  if (const auto target = intersect_plane(cursor.ray, grab_plane_point_, facing)) {
    (void)scene_.set_drag({*grabbed_, *target});  // a picked particle and a finite point
  }
}

void ClothView::release(const Cursor& /*cursor*/, bool moved) {
  if (grabbed_ && !moved) {
    if (auto toggled = scene_.toggle_pin(*grabbed_); !toggled) message_ = toggled.error().message;
  }
  scene_.clear_drag();
  grabbed_.reset();
}

}  // namespace animkit::viewer
