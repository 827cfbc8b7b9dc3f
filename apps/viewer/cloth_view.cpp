#include "cloth_view.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <utility>
#include <vector>

#include "animkit/cloth/integrator_registry.h"
#include "animkit/scene/cloth_scenes.h"

namespace animkit::viewer {

namespace {
constexpr double kClothGrabRadiusPx = 12.0;

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

ClothView::ClothView(ClothScene scene) : scene_(std::move(scene)) {}

Result<ClothView> ClothView::create(const ClothSceneOptions& options) {
  auto scene = ClothScene::create(options);
  if (!scene) return fail(scene.error().message);
  return ClothView(std::move(*scene));
}

Result<ClothView> ClothView::create(const ClothWorldDesc& world, const std::string& name) {
  auto scene = ClothScene::create(world, name);
  if (!scene) return fail(scene.error().message);
  ClothView view(std::move(*scene));
  if (!find_cloth_scene(name)) view.files_.push_back({name, world});
  return view;
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

void ClothView::apply(const ClothWorldDesc& world) {
  if (auto applied = scene_.apply_world(world); !applied)
    message_ = applied.error().message;
  else
    message_.clear();
}

void ClothView::load(const ClothWorldDesc& world, const std::string& name) {
  if (auto loaded = scene_.load(world, name); !loaded) {
    message_ = loaded.error().message;
    return;
  }
  message_.clear();
  grabbed_.reset();
  collider_grabbed_ = false;
  new_view_ = true;
}

void ClothView::scene_menu() {
  if (ImGui::BeginCombo("Scene", scene_.name().c_str())) {
    for (const ClothSceneEntry& entry : cloth_scenes()) {
      if (ImGui::Selectable(entry.name.data(), entry.name == scene_.name()))
        load(entry.make(), std::string(entry.name));
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", entry.summary.data());
    }
    for (const NamedClothWorld& file : files_) {
      if (ImGui::Selectable(file.name.c_str(), file.name == scene_.name()))
        load(file.world, file.name);
    }
    ImGui::EndCombo();
  }
  if (const ClothSceneEntry* entry = find_cloth_scene(scene_.name()))
    ImGui::TextWrapped("%s", entry->summary.data());
}

// The world's settings as controls: the lab's per-particle parameters for the lab's grid, the
// material and sheet otherwise; the time step, solver, contact and wind for every scene. A
// change is applied at once and the cloth keeps moving (a new grid size starts over).
void ClothView::world_controls() {
  ClothWorldDesc w = scene_.world();
  bool changed = false;
  const auto slider = [&](const char* label, double& value, float lo, float hi, const char* fmt,
                          ImGuiSliderFlags flags = 0) {
    float v = static_cast<float>(value);
    if (ImGui::SliderFloat(label, &v, lo, hi, fmt, flags)) {
      value = v;
      changed = true;
    }
  };
  if (scene_.lab_parameters()) {
    GridClothOptions& g = std::get<GridClothOptions>(w.cloth);
    slider("Mass", g.mass, 0.5f, 10.0f, "%.2f");
    slider("Stiffness", g.stiffness, 10.0f, 300.0f, "%.0f");
    slider("Damping", g.damping, 0.1f, 10.0f, "%.2f");
    slider("Gravity", g.gravity, 0.1f, 1.0f, "%.2f");
    if (ImGui::SliderInt("Grid cells", &g.cells, 2, 60)) changed = true;
  } else {
    const char* material = w.material_name.empty() ? "custom" : w.material_name.c_str();
    if (const auto* g = std::get_if<GridClothOptions>(&w.cloth)) {
      ImGui::Text("Sheet       %s, %d x %d cells, %.2f m", material, g->cells, g->cells, g->size);
    } else {
      ImGui::Text("Sheet       %s, from a mesh", material);
    }
    const auto* grid = std::get_if<GridClothOptions>(&w.cloth);
    const auto& m = grid ? grid->material : std::get<MeshClothOptions>(w.cloth).material;
    if (m) {
      ImGui::Text("Material    %.3g kg/m^2, stretch %.4g N/m", m->density, m->stretch);
      ImGui::Text("            shear %.4g N/m, bending %.3g N m", m->shear, m->bending);
    }
    ImGui::Text("Gravity     %.2f m/s^2", scene_.simulator().model().gravity);
  }
  float step_ms = static_cast<float>(1000.0 * w.time_step);
  if (ImGui::SliderFloat("Time step", &step_ms, 1.0f, 100.0f, "%.1f ms")) {
    w.time_step = step_ms / 1000.0;
    changed = true;
  }
  const IntegratorEntry& current = integrator_entry(w.simulation.integrator);
  if (ImGui::BeginCombo("Integrator", current.name.data())) {
    for (const IntegratorEntry& entry : cloth_integrators()) {
      if (ImGui::Selectable(entry.name.data(), &entry == &current)) {
        const auto tolerance = tolerance_of(w.simulation.integrator);
        w.simulation.integrator = entry.defaults;
        if (tolerance && !scene_.lab_parameters())
          set_tolerance(w.simulation.integrator, *tolerance);
        changed = true;
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", entry.summary.data());
    }
    ImGui::EndCombo();
  }
  if (const auto tolerance = tolerance_of(w.simulation.integrator)) {
    float exponent = static_cast<float>(std::log10(*tolerance));
    if (ImGui::SliderFloat("Tolerance", &exponent, -8.0f, -2.0f, "1e%.1f")) {
      set_tolerance(w.simulation.integrator, std::pow(10.0, static_cast<double>(exponent)));
      changed = true;
    }
  }
  if (w.has_contact()) {
    double thickness_mm = 1000.0 * w.contact.thickness;
    slider("Thickness", thickness_mm, 0.5f, 10.0f, "%.1f mm");
    w.contact.thickness = thickness_mm / 1000.0;
    if (ImGui::Checkbox("Self-contact", &w.contact.self_contact)) changed = true;
  }
  if (w.air) {
    float wind[3] = {static_cast<float>(w.air->wind.velocity.x()),
                     static_cast<float>(w.air->wind.velocity.y()),
                     static_cast<float>(w.air->wind.velocity.z())};
    if (ImGui::SliderFloat3("Wind m/s", wind, -10.0f, 10.0f, "%.1f")) {
      w.air->wind.velocity = Vec3(wind[0], wind[1], wind[2]);
      changed = true;
    }
  }
  if (changed) apply(w);
}

void ClothView::readouts() {
  const ClothModel& model = scene_.simulator().model();
  const std::size_t colliders = scene_.colliders().size();
  ImGui::Text("%d particles, %d springs, %zu collider%s", model.particle_count(),
              model.spring_count(), colliders, colliders == 1 ? "" : "s");
  if (const auto& step = scene_.last_step()) {
    ImGui::Text("Step time   %.3f ms", step->ms);
    ImGui::Text("Newton      %d iterations (%d CG)", step->newton_iterations,
                step->linear_iterations);
    ImGui::Text("Converged   %s", step->converged ? "yes" : "no");
    if (step->has_contact) {
      ImGui::Text("Contacts    %d pairs, closest %.3f mm", step->contact_pairs,
                  1000.0 * step->min_contact_distance);
      ImGui::Text("CCD bound   %.3f of a step", step->step_bound_min);
    }
    ImGui::Text("Energy      %.4g", step->energy);
  }
  energy_plot(scene_.energy_history(), 90.0f);
}

void ClothView::panel() {
  scene_menu();
  world_controls();
  if (ImGui::Button(playing_ ? "Stop" : "Start")) playing_ = !playing_;
  ImGui::SameLine();
  if (ImGui::Button("Step")) {
    playing_ = false;
    step_once();
  }
  ImGui::SameLine();
  if (ImGui::Button("Reset")) {
    if (auto reset = scene_.restart(); !reset)
      message_ = reset.error().message;
    else
      message_.clear();
  }
  ImGui::Checkbox("Surface", &style_.surface);
  ImGui::SameLine();
  ImGui::Checkbox("Springs", &style_.springs);
  ImGui::SameLine();
  ImGui::Checkbox("Particles", &style_.particles);
  if (!scene_.colliders().empty() || scene_.contact()) {
    ImGui::Checkbox("Colliders", &style_.colliders);
    ImGui::SameLine();
    ImGui::Checkbox("Contact points", &style_.contacts);
  }
  ImGui::Separator();
  readouts();
  if (!message_.empty()) ImGui::TextColored(ImVec4(0.9f, 0.2f, 0.2f, 1.0f), "%s", message_.c_str());
  ImGui::Separator();
  ImGui::TextWrapped(
      "Drag a particle to pull it on a spring; click one to pin or unpin it. Drag a collider to "
      "push it into the cloth.");
}

bool ClothView::press(const Cursor& cursor) {
  const ClothPick pick = scene_.pick_handle(*cursor.camera, cursor.x, cursor.y, cursor.view_width,
                                            cursor.view_height, kClothGrabRadiusPx);
  if (pick.collider) {
    scene_.grab_collider(*pick.collider);
    collider_grabbed_ = true;
    grab_plane_point_ = pick.collider->point;
    return true;
  }
  grabbed_ = pick.particle;
  if (!grabbed_) return false;
  grab_plane_point_ = scene_.simulator().state().position(*grabbed_);
  return true;
}

void ClothView::drag(const Cursor& cursor) {
  if (!grabbed_ && !collider_grabbed_) return;
  // The handle moves in the plane through where it was grabbed, facing the camera.
  const Vec3 facing = cursor.camera->eye() - cursor.camera->focus;
  const auto target = intersect_plane(cursor.ray, grab_plane_point_, facing);
  if (!target) return;
  if (collider_grabbed_) {
    if (auto moved = scene_.drag_collider_to(*target); !moved) message_ = moved.error().message;
    return;
  }
  (void)scene_.set_drag({*grabbed_, *target});  // a picked particle and a finite point
}

void ClothView::release(const Cursor& /*cursor*/, bool moved) {
  if (collider_grabbed_) {
    scene_.release_collider();
    collider_grabbed_ = false;
    return;
  }
  if (grabbed_ && !moved) {
    if (auto toggled = scene_.toggle_pin(*grabbed_); !toggled) message_ = toggled.error().message;
  }
  scene_.clear_drag();
  grabbed_.reset();
}

}  // namespace animkit::viewer
