#include "ik_view.h"

#include <imgui.h>

#include "animkit/trajectory/lab_shapes.h"

namespace animkit::viewer {

namespace {
constexpr double kGrabRadiusPx = 16.0;

std::string shape_names() {
  std::string names;
  for (LabShape s : all_lab_shapes())
    names += (names.empty() ? "" : ", ") + std::string(to_string(s));
  return names;
}
}  // namespace

IkView::IkView(IkScene scene, int shape) : scene_(std::move(scene)), shape_(shape) {}

Result<IkView> IkView::create(const IkViewOptions& options) {
  const auto shape = parse_lab_shape(options.shape);
  if (!shape) {
    return fail("unknown shape '" + options.shape + "' (expected one of: " + shape_names() + ")");
  }
  IkSceneOptions scene_options;
  scene_options.solver = options.solver;
  auto scene = IkScene::create(lab_arm(), lab_shape_targets(*shape), scene_options);
  if (!scene) return fail(scene.error().message);
  int index = 0;
  while (all_lab_shapes()[index] != *shape) ++index;
  return IkView(std::move(*scene), index);
}

void IkView::advance(double /*seconds*/) {
  // The lab's app solves one target per displayed frame; speed scales that.
  if (!playing_ || dragging_) return;
  pending_ += speed_;
  while (pending_ >= 1.0) {
    scene_.advance();
    pending_ -= 1.0;
  }
}

void IkView::panel() {
  int solver = scene_.options().solver == IkSolverKind::ccd ? 0 : 1;
  if (ImGui::Combo("Solver", &solver, "CCD\0FABRIK\0")) {
    scene_.set_solver(solver == 0 ? IkSolverKind::ccd : IkSolverKind::fabrik);
  }
  const auto shapes = all_lab_shapes();
  const std::string current(to_string(shapes[shape_]));
  if (ImGui::BeginCombo("Shape", current.c_str())) {
    for (int i = 0; i < static_cast<int>(shapes.size()); ++i) {
      const std::string label(to_string(shapes[i]));
      if (ImGui::Selectable(label.c_str(), i == shape_)) {
        shape_ = i;
        (void)scene_.set_targets(lab_shape_targets(shapes[i]));  // built-in: always valid
        pending_ = 0.0;
      }
    }
    ImGui::EndCombo();
  }
  if (ImGui::Button(playing_ ? "Pause" : "Start")) playing_ = !playing_;
  ImGui::SameLine();
  if (ImGui::Button("Step")) {
    playing_ = false;
    scene_.advance();
  }
  ImGui::SameLine();
  if (ImGui::Button("Reset")) {
    scene_.reset();
    pending_ = 0.0;
  }
  float speed = static_cast<float>(speed_);
  if (ImGui::SliderFloat("Speed", &speed, 0.1f, 20.0f, "%.1f targets/frame",
                         ImGuiSliderFlags_Logarithmic)) {
    speed_ = speed;
  }

  ImGui::Separator();
  const int count = static_cast<int>(scene_.targets().size());
  ImGui::Text("Target      %d / %d", scene_.lap_finished() ? count : scene_.next_target(), count);
  if (const auto& last = scene_.last_solve()) {
    ImGui::Text("Iterations  %d", last->result.iterations);
    ImGui::Text("Error       %.2e", last->result.error);
    ImGui::Text("Solve time  %.2f us", last->solve_time_us);
    ImGui::Text("Converged   %s", last->result.converged ? "yes" : "no");
    if (last->result.reachable) {
      ImGui::Text("Reachable   yes");
    } else {
      ImGui::TextColored(ImVec4(1.0f, 0.55f, 0.0f, 1.0f), "Reachable   no: the arm points at it");
    }
  } else {
    ImGui::TextDisabled("No solve yet: press Start or Step.");
  }
  ImGui::Separator();
  ImGui::TextWrapped(
      "Drag the arm's tip (white) to move the target: the arm follows on the plane y = 0. "
      "Targets green, drawn path red, out-of-reach targets orange.");
}

bool IkView::press(const Cursor& cursor) {
  const auto tip =
      cursor.camera->project(scene_.pose().end_effector(), cursor.view_width, cursor.view_height);
  if (!tip || std::hypot(tip->x() - cursor.x, tip->y() - cursor.y) > kGrabRadiusPx) return false;
  dragging_ = true;
  playing_ = false;
  follow_cursor(cursor);
  return true;
}

void IkView::drag(const Cursor& cursor) {
  if (dragging_) follow_cursor(cursor);
}

void IkView::release(const Cursor& /*cursor*/, bool /*moved*/) {
  dragging_ = false;
}

void IkView::follow_cursor(const Cursor& cursor) {
  if (const auto point = intersect_horizontal_plane(cursor.ray, 0.0)) {
    (void)scene_.follow(*point);  // a finite point on the plane: always a valid target
  }
}

void IkView::describe(DrawList& out) const {
  scene_.describe(out);
  // The dragged target, unless the scene already marks it as out of reach.
  const auto& last = scene_.last_solve();
  if (dragging_ && last && last->result.reachable) {
    out.add_point(last->target, palette::end_effector, 12.0f);
  }
}

}  // namespace animkit::viewer
