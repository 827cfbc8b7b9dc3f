#include "ik_view.h"

#include <imgui.h>

namespace animkit::viewer {

namespace {
constexpr double kIkGrabRadiusPx = 16.0;
}  // namespace

IkView::IkView(IkScene scene, std::vector<Entry> entries, int selected, DrawingLayout layout,
               PreparedDrawing drawing)
    : scene_(std::move(scene)),
      entries_(std::move(entries)),
      selected_(selected),
      layout_(std::move(layout)),
      drawing_(std::move(drawing)) {}

Result<IkView> IkView::create(const IkViewOptions& options) {
  std::vector<Entry> entries;
  for (const std::string& name : builtin_shape_names()) {
    DrawingSource source;
    source.shape = name;
    entries.push_back({name, source});
  }
  const auto chain = build_chain(lab_arm());
  if (!chain) return fail(chain.error().message);
  auto drawing = prepare_drawing(options.source, options.layout, *chain);
  if (!drawing) return fail(drawing.error().message);
  int selected = 0;
  if (options.source.kind == DrawingSourceKind::shape) {
    while (entries[selected].name != options.source.shape) ++selected;
  } else {
    selected = static_cast<int>(entries.size());
    entries.push_back({drawing->name, options.source});
  }
  IkSceneOptions scene_options;
  scene_options.solver = options.solver;
  auto scene = IkScene::create(lab_arm(), drawing->trajectory, scene_options);
  if (!scene) return fail(scene.error().message);
  return IkView(std::move(*scene), std::move(entries), selected, options.layout,
                std::move(*drawing));
}

void IkView::select(int index) {
  auto drawing = prepare_drawing(entries_[index].source, layout_, scene_.chain());
  if (!drawing) {
    message_ = drawing.error().message;
    return;
  }
  if (auto set = scene_.set_trajectory(drawing->trajectory); !set) {
    message_ = set.error().message;
    return;
  }
  message_.clear();
  selected_ = index;
  drawing_ = std::move(*drawing);
  pending_ = 0.0;
}

void IkView::drawing_panel() {
  if (ImGui::BeginCombo("Shape", entries_[selected_].name.c_str())) {
    for (int i = 0; i < static_cast<int>(entries_.size()); ++i) {
      if (ImGui::Selectable(entries_[i].name.c_str(), i == selected_)) select(i);
    }
    ImGui::EndCombo();
  }
  ImGui::InputText("##text", text_, sizeof text_);
  ImGui::SameLine();
  if (ImGui::Button("Draw text")) {
    DrawingSource source;
    source.kind = DrawingSourceKind::text;
    source.text = text_;
    const std::string name = "text " + source.text;
    int index = 0;
    while (index < static_cast<int>(entries_.size()) && entries_[index].name != name) ++index;
    if (index == static_cast<int>(entries_.size())) entries_.push_back({name, source});
    select(index);
    if (!message_.empty() && index + 1 == static_cast<int>(entries_.size())) entries_.pop_back();
  }
  bool even = layout_.spacing.has_value();
  float spacing = static_cast<float>(layout_.spacing.value_or(0.01));
  bool changed = ImGui::Checkbox("Set spacing", &even);
  ImGui::SameLine();
  changed |= ImGui::SliderFloat("##spacing", &spacing, 0.002f, 0.05f, "%.3f",
                                ImGuiSliderFlags_Logarithmic);
  if (changed) {
    layout_.spacing = even ? std::optional<double>(spacing) : std::nullopt;
    select(selected_);
  }
  ImGui::Text("%d stroke%s, %zu targets, spacing cv %.3f", drawing_.strokes,
              drawing_.strokes == 1 ? "" : "s", drawing_.trajectory.targets.size(),
              drawing_.spacing_after.cv);
  if (!message_.empty()) ImGui::TextColored(ImVec4(0.9f, 0.2f, 0.2f, 1.0f), "%s", message_.c_str());
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
  drawing_panel();
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
      "Targets green, pen-up travel grey, drawn path red, out-of-reach targets orange.");
}

bool IkView::press(const Cursor& cursor) {
  const auto tip =
      cursor.camera->project(scene_.pose().end_effector(), cursor.view_width, cursor.view_height);
  if (!tip || std::hypot(tip->x() - cursor.x, tip->y() - cursor.y) > kIkGrabRadiusPx) return false;
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
